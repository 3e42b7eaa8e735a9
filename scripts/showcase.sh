#!/usr/bin/env bash
# Quick start (1): build, then render scenes/showcase.pov to showcase.png in the current directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
"$root/build/povtrace" +W800 +H600 +A0.3 "$root/scenes/showcase.pov" +Oshowcase.png
