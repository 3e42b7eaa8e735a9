#!/bin/bash
# Regenerates reference/animation/NAME/ for every case of reference/animation/cases.txt with POV-Ray, and rewrites
# reference/animation/README.md.
# Usage: reference/make_animation_references.sh [NAME...]   (no names = every case)
# Each case's .ini folder (under POV-Ray's sample scenes, $POVRAY_SAMPLES or /usr/share/povray-3.7/scenes) is copied
# to a scratch folder, so that the .ini and the scene run from their own folder and the files they write (#fopen
# HTML pages) land there, and rendered there with exactly:
#   povray -D INI_FILE_NAME +W160 +H120 +FE -A +GDdebug.txt [switches]
# where [switches] are the case's (cases.txt). Every file the run adds to the folder (the frames, named as POV-Ray
# names them, the #debug file debug.txt, HTML pages) is moved to reference/animation/NAME/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$here/animation
samples=${POVRAY_SAMPLES:-/usr/share/povray-3.7/scenes}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -d "$samples/animations" ] || { echo "no POV-Ray sample scenes in $samples (Debian package povray-examples)"; exit 1; }

failed=0
found=0
while read -r name ini switches; do
  case $name in ''|'#'*) continue ;; esac
  if [ $# -gt 0 ]; then
    wanted=0
    for n in "$@"; do [ "$n" = "$name" ] && wanted=1; done
    [ $wanted -eq 1 ] || continue
  fi
  found=$((found + 1))
  read -r -a extra <<< "$switches"
  run=$work/$name
  cp -R "$samples/$(dirname "$ini")" "$run"
  (cd "$run" && ls -A) > "$work/$name.before"
  if (cd "$run" && povray -D "$(basename "$ini")" +W160 +H120 +FE -A +GDdebug.txt "${extra[@]}") \
       > "$work/$name.log" 2>&1; then
    rm -rf "${out:?}/$name"
    mkdir -p "$out/$name"
    (cd "$run" && ls -A) | grep -vxF -f "$work/$name.before" | while read -r f; do mv "$run/$f" "$out/$name/"; done
    echo "ok    $name ($(ls "$out/$name" | grep -c '\.exr$') frames)"
  else
    echo "FAIL  $name (last lines of POV-Ray's output follow)"; tail -15 "$work/$name.log"; failed=1
  fi
done < "$out/cases.txt"
if [ $# -gt 0 ] && [ "$found" -ne $# ]; then echo "FAIL  some of the names $* are not in cases.txt"; failed=1; fi

version=$(povray --version 2>&1 | grep -m1 '^POV-Ray')
cat > "$out/README.md" <<README
# Animation reference frames

\`NAME/\` holds what POV-Ray wrote when it rendered the sample animation of case NAME of \`cases.txt\`, made by
\`../make_animation_references.sh\` (run it again after changing a case; \`make_animation_references.sh NAME...\`
redoes only those): the frames under the names POV-Ray gave them, its #debug file \`debug.txt\` and any file the
scene wrote (the portfolio's HTML pages).

- POV-Ray version (first line of \`povray --version\`): \`$version\`
- Scenes: Debian's povray-examples, \`/usr/share/povray-3.7/scenes/\` (not copied into this repository).
- Command, run in a scratch copy of the .ini's folder, for each case:
  \`povray -D INI_FILE_NAME +W160 +H120 +FE -A +GDdebug.txt [switches]\` with the case's switches (frame subset).
  No anti-aliasing (the .ini files turn it on; \`-A\` after the .ini turns it off), 160×120, OpenEXR output. Debian's
  /etc/povray/3.7/povray.ini is read too (Library_Path entries, Verbose, Bounding_Threshold).
- Generated: $(date -u +%Y-%m-%d)

The regression test \`animation_samples\` (\`tests/regression/animation_samples_test.cpp\`) runs povtrace with the
same command and checks that it writes the same set of file names, every frame within PSNR ≥ 50 dB and at most
0.1 % of pixels off by more than 1/255, and every other file byte for byte equal.
README
exit $failed
