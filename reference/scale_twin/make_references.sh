#!/bin/bash
# Regenerates reference/scale_twin/S_<scale>.exr: POV-Ray's renders of tests/stress/scale_twin.pov at every scale
# of the --povray-tolerances test (tests/stress/CMakeLists.txt), and rewrites README.md next to them.
# Usage: reference/scale_twin/make_references.sh
# Each scale is rendered from tests/stress/ with exactly:
#   povray -D -A +W160 +H120 +FE Declare=S=<scale> +O<here>/S_<scale>.exr scale_twin.pov
# POV-Ray refuses S = 1e-6 (its camera check is absolute); the script requires that failure and writes no image.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
stress=$(cd "$here/../../tests/stress" && pwd)
scales=(1e-5 1e-4 1e-3 0.01 0.1 1 10 100 1e3 1e4 1e5 1e6)
aborting_scale=1e-6
abort_message="Camera location and look_at point must be different."
abort_grep="Camera location and look_at point"   # POV-Ray wraps the message after these words
log=$(mktemp)
trap 'rm -f "$log"' EXIT

cd "$stress"
for s in "${scales[@]}"; do
  if povray -D -A +W160 +H120 +FE "Declare=S=$s" "+O$here/S_$s.exr" scale_twin.pov > "$log" 2>&1; then
    echo "ok    S = $s"
  else
    echo "FAIL  S = $s (last lines of POV-Ray's output follow)"; tail -15 "$log"; exit 1
  fi
done
rm -f "$here/S_$aborting_scale.exr"
if povray -D -A +W160 +H120 +FE "Declare=S=$aborting_scale" "+O$here/S_$aborting_scale.exr" scale_twin.pov \
    > "$log" 2>&1 || ! grep -q "$abort_grep" "$log" || [ -e "$here/S_$aborting_scale.exr" ]; then
  echo "POV-Ray did not refuse S = $aborting_scale as expected:"; tail -15 "$log"; exit 1
fi
echo "ok    S = $aborting_scale refused: $abort_message"

version=$(povray --version 2>&1 | grep -m1 '^POV-Ray')
cat > "$here/README.md" <<README
# POV-Ray's renders of the scale twin

\`S_<scale>.exr\` is POV-Ray's render of \`tests/stress/scale_twin.pov\` with every length multiplied by the scale,
written by \`make_references.sh\` (run it again after changing the scene). The ctests \`stress.povray_tolerances.<scale>\`
render the same with \`povtrace --povray-tolerances\` and require the regression thresholds against these (PSNR ≥ 50 dB,
at most 0.1 % of pixels off by more than 1/255): POV-Ray's absolute tolerances, artefacts included, at every scale.

- POV-Ray version (first line of \`povray --version\`): \`$version\`
- Command, run from \`tests/stress/\`, for each scale: \`povray -D -A +W160 +H120 +FE Declare=S=<scale> +O../../reference/scale_twin/S_<scale>.exr scale_twin.pov\`
  (no anti-aliasing, 160×120, OpenEXR half float), scales ${scales[*]}.
- S = $aborting_scale has no image: POV-Ray stops parsing with "Parse Error: $abort_message"
  (its look_at check, VSumSqr(look_at − location) < 1e-10, is absolute); the test requires povtrace
  --povray-tolerances to stop with the same error, exit 1 and no image.
- Generated: $(date -u +%Y-%m-%d)
README
