#!/usr/bin/env bash
# An MPI render (mpirun -np 3: rank 0 schedules, two workers render tiles) must be the single-process render's
# file, byte for byte. Usage: same_image.sh MPIRUN POVTRACE WORK_DIR SCENE [switches…]
set -euo pipefail
mpirun=$1 povtrace=$2 work=$3 scene=$4
shift 4
mkdir -p "$work"
rm -f "$work"/one.* "$work"/mpi.*
# No extension given: povtrace appends the format's (.png, .exr …).
"$povtrace" "$@" +O"$work/one" "$scene"
"$mpirun" --allow-run-as-root --oversubscribe -np 3 "$povtrace" "$@" +O"$work/mpi" "$scene"
one=("$work"/one.*) mpi=("$work"/mpi.*)
[[ ${#one[@]} -eq 1 && ${#mpi[@]} -eq 1 && -f ${one[0]} && -f ${mpi[0]} ]] || { echo "FAIL: ${one[*]} ${mpi[*]}"; exit 1; }
cmp "${one[0]}" "${mpi[0]}"
echo "same file: $*"
