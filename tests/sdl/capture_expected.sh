#!/usr/bin/env bash
# Regenerates tests/sdl/expected/NAME.txt, POV-Ray 3.7's #debug output for tests/sdl/cases/NAME.pov, and
# rewrites expected/POVRAY_VERSION.
# Usage: tests/sdl/capture_expected.sh [NAME...]   (no names = every case)
#
# Each case runs in a fresh temporary copy of cases/ (file I/O cases write there) with
#   povray +W8 +H8 -D -V -GR -GS -GW +INAME.pov +O/dev/null
# POV-Ray 3.7 prints every stream to stderr. The debug stream (#debug) is on by default; -GR -GS -GW turn off
# the render, statistics and warning streams (#warning text and parse warnings go to the warning stream), so
# between the "==== [Parsing...]" and "==== [Rendering...]" banners only #debug text remains. Fatal errors
# stay on: a case POV-Ray rejects is an error here. (Note: "-GA +GD", which looks like "everything off, then
# debug on", leaves the debug stream off in 3.7.0.10.)
# Two console quirks shape the cases: POV-Ray wraps console lines at 80 columns, so a case may not print a
# line of 80 characters or more (checked below); and it drops a last #debug line that has no "\n".
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cases="$here/cases"
expected="$here/expected"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ $# -gt 0 ]; then names=("$@"); else
  names=()
  for f in "$cases"/*.pov; do names+=("$(basename "${f%.pov}")"); done
fi

failed=0
for n in "${names[@]}"; do
  if [ ! -f "$cases/$n.pov" ]; then echo "FAIL  $n: no $cases/$n.pov"; failed=1; continue; fi
  run="$work/$n"
  mkdir -p "$run"
  cp -R "$cases"/. "$run"/
  status=0
  (cd "$run" && povray +W8 +H8 -D -V -GR -GS -GW "+I$n.pov" +O/dev/null) > "$work/$n.log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    echo "FAIL  $n: povray exit status $status; its output from the parse on:"
    sed -n '/^==== \[Parsing/,$p' "$work/$n.log" | head -20
    failed=1
    continue
  fi
  # The text between the two banners, banners excluded.
  awk '/^==== \[Parsing\.\.\.\] /{on=1; next} /^==== \[Rendering\.\.\.\] /{on=0} on' "$work/$n.log" > "$work/$n.txt"
  if awk 'length($0) >= 80 {bad=1} END {exit !bad}' "$work/$n.txt"; then
    echo "FAIL  $n: a line of 80 characters or more (POV-Ray's console wraps it); shorten it:"
    awk 'length($0) >= 80' "$work/$n.txt" | head -3
    failed=1
    continue
  fi
  cp "$work/$n.txt" "$expected/$n.txt"
  echo "ok    $n ($(wc -l < "$expected/$n.txt") lines)"
done

povray --version 2>&1 | grep -m1 '^POV-Ray' > "$expected/POVRAY_VERSION"
exit $failed
