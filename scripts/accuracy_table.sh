#!/usr/bin/env bash
# Renders every scene that has a POV-Ray reference with the reference's switches and prints a Markdown table of
# the povdiff figures (the accuracy table of README and of closing notes). Needs a built tree (scripts/build.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| scene | PSNR (dB) | RMSE | max abs error | pixels off > 1/255 |"
echo "|---|---:|---:|---:|---:|"
cd "$root/scenes"
for ref in "$root"/reference/*.exr; do
  name=$(basename "$ref" .exr)
  # The scene's own extra switches ("// switches: …"), as the reference was made (reference/make_references.sh).
  read -r -a extra <<< "$(grep -m1 '^// switches:' "$name.pov" | sed 's|^// switches:||')"
  if ! "$root/build/povtrace" -D -A +W320 +H240 +FE "${extra[@]}" +O"$out/$name.exr" "$name.pov" 2>"$out/$name.log"; then
    echo "| $name | render failed: $(head -1 "$out/$name.log") | | | |"
    continue
  fi
  line=$("$root/build/povdiff" "$out/$name.exr" "$ref" | tail -1 || true)
  get() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$line"; }
  echo "| $name | $(get psnr) | $(get rmse) | $(get max) | $(get over) |"
done
