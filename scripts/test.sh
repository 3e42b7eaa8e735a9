#!/usr/bin/env bash
# Quick start (2): build, then run the whole test suite (unit tests and one image test per scene) with ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)"
