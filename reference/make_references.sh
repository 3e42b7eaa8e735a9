#!/bin/bash
# Regenerates reference/NAME.exr for every scenes/NAME.pov with POV-Ray, and rewrites reference/README.md.
# Usage: reference/make_references.sh [NAME...]   (no names = every scene)
# Each scene is rendered from the scenes/ folder (so relative paths resolve as POV-Ray would) with exactly:
#   povray -D -A +W320 +H240 +FE [switches] +O../reference/NAME.exr NAME.pov
# where [switches] are those of a "// switches: …" line in the scene (e.g. "+A0.3 +R3 -J" or "+UA"), if any.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../scenes" && pwd)
log_dir=$(mktemp -d)
trap 'rm -rf "$log_dir"' EXIT

if [ $# -gt 0 ]; then names=("$@"); else
  names=()
  for f in "$scenes"/*.pov; do names+=("$(basename "${f%.pov}")"); done
fi

failed=0
cd "$scenes"
for n in "${names[@]}"; do
  # A scene may ask for extra switches (antialiasing, alpha) on a line "// switches: …" near its top.
  read -r -a extra <<< "$(grep -m1 '^// switches:' "$n.pov" | sed 's|^// switches:||')"
  if povray -D -A +W320 +H240 +FE "${extra[@]}" "+O../reference/$n.exr" "$n.pov" > "$log_dir/$n.log" 2>&1; then
    echo "ok    $n"
  else
    echo "FAIL  $n (last lines of POV-Ray's output follow)"; tail -15 "$log_dir/$n.log"; failed=1
  fi
done

version=$(povray --version 2>&1 | grep -m1 '^POV-Ray')
cat > "$here/README.md" <<README
# Reference images

\`NAME.exr\` is POV-Ray's render of \`../scenes/NAME.pov\`, written by \`make_references.sh\` (run it again after
changing a scene; \`make_references.sh NAME...\` redoes only those).

- POV-Ray version (first line of \`povray --version\`): \`$version\`
- Command, run from the \`scenes/\` folder, for each scene: \`povray -D -A +W320 +H240 +FE [switches] +O../reference/NAME.exr NAME.pov\`
  (no anti-aliasing, 320×240, OpenEXR output: half float, RGB, zip, linear, unclipped), where [switches] are those
  of a \`// switches: …\` line in the scene, if it has one (antialiased scenes with \`-J\`, alpha output with \`+UA\`). Debian's
  /etc/povray/3.7/povray.ini is read too; besides settings the command overrides (size, output type, display) it
  adds Library_Path entries, Verbose=On and Bounding_Threshold=3, none of which changes the image. Threads are
  POV-Ray's default (all cores); nothing in these scenes depends on the thread count.
- Generated: $(date -u +%Y-%m-%d)

The regression tests (\`tests/regression\`) render every scene that has a reference here with povtrace using the same
switches and compare with \`povdiff\` (PSNR ≥ 50 dB, at most 0.1 % of pixels off by more than 1/255).

\`scale_twin/\` holds POV-Ray's renders of \`tests/stress/scale_twin.pov\` at scales 1e-5 … 1e6 for the
\`--povray-tolerances\` tests, with their own script and README.

\`animation/\` holds POV-Ray's frames of its sample animations for the \`animation_samples\` tests, with their own
script (\`make_animation_references.sh\`) and README.

\`media_random/\` holds POV-Ray's renders of \`../scenes/media_random/\` (media sampling that is random in POV-Ray with
more than one thread: a +WT1 reference and three +WT2 renders each), with their own script
(\`make_media_random_references.sh\`) and README. \`media_scenes.md\` lists the media scenes (\`media_*\`, issue 20): what
each tests, POV-Ray's render times, determinism, and the Debian sample scenes that use media.

\`photons_random/\` holds POV-Ray's renders of \`../scenes/photons_random/\` (photon maps shot from several lights or
targets, which POV-Ray shoots differently with more than one thread: a +WT1 reference and three +WT2 renders each),
made by \`KIND=photons_random make_media_random_references.sh\`, with its own README.
README
exit $failed
