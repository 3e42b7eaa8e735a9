#!/usr/bin/env bash
# An MPI render (mpirun -np 3: rank 0 schedules, two workers render tiles) must be the single-process render's
# file, byte for byte, and print the same #debug lines once (+GD file; rank 0 writes those of worker 1). Usage: same_image.sh MPIRUN POVTRACE WORK_DIR SCENE [switches…]
set -euo pipefail
# Under AddressSanitizer (scripts/test_sanitized.sh) OpenMPI's start-up allocations are reported as leaks at exit,
# from plugins it has already unloaded, so no suppression can name them: leak checking is off for the ranks here
# (every other test still leak-checks povtrace's code; the sanitizers' other checks stay on).
if [[ -n ${ASAN_OPTIONS:-} ]]; then export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"; fi
mpirun=$1 povtrace=$2 work=$3 scene=$4
shift 4
mkdir -p "$work"
rm -f "$work"/one.* "$work"/mpi.*
# No extension given: povtrace appends the format's (.png, .exr …).
rm -f "$work"/*.debug
"$povtrace" "$@" +GD"$work/one.debug" +O"$work/one" "$scene"
"$mpirun" --allow-run-as-root --oversubscribe -np 3 "$povtrace" "$@" +GD"$work/mpi.debug" +O"$work/mpi" "$scene"
cmp "$work/one.debug" "$work/mpi.debug" || { echo "FAIL: different #debug output"; exit 1; }
one=("$work"/one.[!d]*) mpi=("$work"/mpi.[!d]*)
[[ ${#one[@]} -eq 1 && ${#mpi[@]} -eq 1 && -f ${one[0]} && -f ${mpi[0]} ]] || { echo "FAIL: ${one[*]} ${mpi[*]}"; exit 1; }
cmp "${one[0]}" "${mpi[0]}"
echo "same file: $*"
