#!/usr/bin/env bash
# povtrace --vs-povray end to end (needs POV-Ray; skipped with 77 without it): an antialiased, jittered scene
# matches POV-Ray (POV-Ray's AA jitter is a fixed lookup that povtrace reproduces); a scene with a jittered area
# light does not match and the verdict names the area light as POV-Ray's randomness; the side-by-side strip is
# written (three images wide).
# Usage: vs_povray_check.sh POVTRACE SCENES_DIR WORK_DIR
set -uo pipefail
povtrace=$1 scenes=$2 work=$3
command -v povray > /dev/null || { echo "povray not installed: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

out=$("$povtrace" --vs-povray +W96 +H72 +A0.3 +R3 +O"$work/aa.png" "$scenes/aa_method1_jitter.pov" 2>&1)
status=$?
echo "$out"
[[ $status -eq 0 ]] || fail "jittered antialiasing: exit $status, expected 0 (a match)"
grep -q "^verdict: match" <<< "$out" || fail "jittered antialiasing: no 'verdict: match'"
[[ -s $work/aa.png ]] || fail "no side-by-side image"
width=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); print(struct.unpack('>I', d[16:20])[0])" "$work/aa.png")
[[ $width -eq 288 ]] || fail "side-by-side strip is $width pixels wide, expected 3 x 96"

out=$("$povtrace" --vs-povray +W96 +H72 -A +O"$work/area.png" "$scenes/area_light_jitter.pov" 2>&1)
status=$?
echo "$out"
[[ $status -eq 1 ]] || fail "jittered area light: exit $status, expected 1 (different)"
grep -q "^verdict: DIFFERENT - but POV-Ray draws this scene's area lights with jitter at random" <<< "$out" ||
  fail "jittered area light: the verdict does not name POV-Ray's random area-light jitter"
echo PASS
