#!/usr/bin/env bash
# Installs (with apt-get) whatever povtrace needs that this Debian machine lacks. Idempotent: a machine that
# already has everything runs no apt-get at all.
set -euo pipefail
packages=(
  cmake g++ make pkg-config        # build
  tao-pegtl-dev                    # PEGTL lexer
  libopenexr-dev libpng-dev libjpeg62-turbo-dev  # image output
  libembree-dev                    # nearest triangle of large meshes
  libgtest-dev                     # unit tests
  povray povray-includes           # reference renders, standard include files, bench comparison
  povray-examples                  # sample scenes: sample_ini_test, animation_samples_tests, scripts/sample_scenes.py
  python3                          # reference/bench scripts
  clang libclang-rt-14-dev         # scripts/fuzz.sh: libFuzzer and the sanitizer runtimes come with clang's
  openmpi-bin libopenmpi-dev       # optional MPI rendering (mpirun -np N povtrace …) and its tests
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=(); [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
