#!/bin/sh
# Every POV-Ray sample .ini under EXAMPLES (Debian's /usr/share/doc/povray/examples) must parse: povtrace reads
# the whole command line before it acts on --version, so `povtrace --no-povray-ini x.ini --version` exits 0
# exactly when x.ini parses. __empty.ini (a template with `Final_Frame=` empty) must fail with exit 2.
# Gzipped samples are decompressed first. Exit 77 (skipped) when the folder is absent.
povtrace=$1
examples=$2
[ -d "$examples" ] || { echo "no $examples; skipped"; exit 77; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
failures=0
count=0
for f in $(find "$examples" -name '*.ini' -o -name '*.ini.gz' | sort); do
  dir=$(dirname "$f")
  ini=$f
  case $f in *.gz) ini=$tmp/$(basename "$f" .gz); gzip -dc "$f" > "$ini" ;; esac
  expected=0
  case $(basename "$ini") in __empty.ini) expected=2 ;; esac
  (cd "$dir" && "$povtrace" --no-povray-ini "$ini" --version > /dev/null 2> "$tmp/err")
  status=$?
  count=$((count + 1))
  if [ "$status" -ne "$expected" ]; then
    echo "FAIL: $f: exit $status, expected $expected"; cat "$tmp/err"; failures=$((failures + 1))
  elif [ "$expected" -eq 2 ] && ! grep -q "Final_Frame" "$tmp/err"; then
    echo "FAIL: $f: the message does not name Final_Frame:"; cat "$tmp/err"; failures=$((failures + 1))
  fi
done
echo "$count sample .ini files, $failures failures"
[ "$count" -gt 0 ] && [ "$failures" -eq 0 ]
