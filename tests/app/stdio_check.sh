#!/usr/bin/env bash
# The povtrace program end to end, for what only a whole run shows: +O- writes the file to standard output (the
# same bytes as +Ofile), +I- reads the scene from standard input, an animation writes one numbered file per frame
# and runs Pre_Frame_Command/Post_Frame_Command per frame with their % codes (only with --allow-shellout).
# Usage: stdio_check.sh POVTRACE WORK_DIR
set -euo pipefail
povtrace=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
cat > scene.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <-3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 } }
sphere { <2 * clock - 1, 0.5, 0>, 0.5 pigment { rgb <clock, 0.5, 1 - clock> } }
POV
common=(--no-povray-ini -D +W48 +H36 -A)

for type in FP FN FT FC FB FH; do
  "$povtrace" "${common[@]}" +$type scene.pov +O- > stdout.img 2> /dev/null
  "$povtrace" "${common[@]}" +$type scene.pov +Ofile 2> /dev/null
  files=(file.*)
  [[ ${#files[@]} -eq 1 ]] || fail "+$type: expected one file, got ${files[*]}"
  # A Radiance header and a Targa extension area carry the time of writing (as POV-Ray's): compare without it
  # (the two runs can fall in different seconds, as they do under the sanitizers).
  LC_ALL=C sed -i '/^CREATION_TIME=/d' stdout.img "${files[0]}"
  if [[ $type == FT || $type == FC ]]; then
    for f in stdout.img "${files[0]}"; do
      python3 - "$f" <<'PY'
import struct, sys
path = sys.argv[1]
data = bytearray(open(path, "rb").read())
extension = struct.unpack_from("<I", data, len(data) - 26)[0]   # TGA 2.0 footer: extension area offset
if extension:
    data[extension + 367:extension + 379] = bytes(12)           # its date/time stamp (6 shorts)
open(path, "wb").write(data)
PY
    done
  fi
  cmp stdout.img "${files[0]}" || fail "+$type: +O- differs from +O${files[0]}"
  rm -f file.* stdout.img
done
echo "ok: +O- equals +Ofile in 6 formats"
# As POV-Ray, JPEG and OpenEXR cannot go to standard output: exit 1, a message, nothing written there.
for type in FJ FE; do
  status=0
  "$povtrace" "${common[@]}" +$type scene.pov +O- > stdout.img 2> stdout.log || status=$?
  [[ $status -eq 1 && ! -s stdout.img ]] || fail "+$type +O-: exit $status, $(wc -c < stdout.img) bytes on stdout"
  grep -q "standard output" stdout.log || fail "+$type +O-: no message: $(cat stdout.log)"
done
echo "ok: JPEG and EXR to standard output are refused"

"$povtrace" "${common[@]}" +FP +Ofile.ppm scene.pov 2> /dev/null
"$povtrace" "${common[@]}" +FP +I- +Ostdin.ppm < scene.pov 2> /dev/null
cmp file.ppm stdin.ppm || fail "+I- renders differently from the file"
echo "ok: +I- reads the scene from standard input"

mkdir frames
"$povtrace" "${common[@]}" +FN +KFI1 +KFF3 +KC --allow-shellout \
  'Pre_Frame_Command=echo pre %n %k %s >> shell.log' 'Post_Frame_Command=echo post %n %o >> shell.log' \
  scene.pov +Oframes/f.png 2> anim.log
[[ $(cd frames && echo *) == "f1.png f2.png f3.png" ]] || fail "frames: $(cd frames && echo *)"
! cmp -s frames/f1.png frames/f2.png || fail "frames 1 and 2 are identical: the clock did not change the scene"
expected="pre 1 0.000000 scene
post 1 frames/f1.png
pre 2 0.333333 scene
post 2 frames/f2.png
pre 3 0.666667 scene
post 3 frames/f3.png"
[[ $(cat shell.log) == "$expected" ]] || fail "shell-outs: got
$(cat shell.log)"
echo "ok: an animation writes numbered frames and runs the frame shell-outs in order"
echo PASS
