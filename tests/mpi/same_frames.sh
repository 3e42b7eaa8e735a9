#!/usr/bin/env bash
# An MPI animation render (mpirun -np 3: rank 0 hands out frames, two workers parse and render each frame whole)
# must write the same files, byte for byte and with the same numbered names, as one process.
# Usage: same_frames.sh MPIRUN POVTRACE WORK_DIR SCENE [switches…]
set -euo pipefail
mpirun=$1 povtrace=$2 work=$3 scene=$4
shift 4
rm -rf "$work/one" "$work/mpi"
mkdir -p "$work/one" "$work/mpi"
"$povtrace" "$@" +O"$work/one/frame" "$scene"
"$mpirun" --allow-run-as-root --oversubscribe -np 3 "$povtrace" "$@" +O"$work/mpi/frame" "$scene"
one=$(cd "$work/one" && ls) mpi=$(cd "$work/mpi" && ls)
[[ -n $one ]] || { echo "FAIL: no frame written"; exit 1; }
[[ $one == "$mpi" ]] || { echo "FAIL: different files"; echo "one: $one"; echo "mpi: $mpi"; exit 1; }
for f in $one; do cmp "$work/one/$f" "$work/mpi/$f"; done
echo "same $(echo "$one" | wc -l) frames: $*"
