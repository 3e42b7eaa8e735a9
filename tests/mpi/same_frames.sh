#!/usr/bin/env bash
# An MPI animation render (mpirun -np 3: rank 0 hands out frames, two workers parse and render each frame whole)
# must write the same files, byte for byte and with the same numbered names, as one process, and the same #debug
# lines (+GD file: rank 0 writes the workers' lines, in the order frames finish, so compared sorted).
# Usage: same_frames.sh MPIRUN POVTRACE WORK_DIR SCENE [switches…]
set -euo pipefail
# Under AddressSanitizer (scripts/test_sanitized.sh) OpenMPI's start-up allocations are reported as leaks at exit,
# from plugins it has already unloaded, so no suppression can name them: leak checking is off for the ranks here
# (every other test still leak-checks povtrace's code; the sanitizers' other checks stay on).
if [[ -n ${ASAN_OPTIONS:-} ]]; then export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"; fi
mpirun=$1 povtrace=$2 work=$3 scene=$4
shift 4
rm -rf "$work/one" "$work/mpi"
mkdir -p "$work/one" "$work/mpi"
"$povtrace" "$@" +GD"$work/one.debug" +O"$work/one/frame" "$scene"
"$mpirun" --allow-run-as-root --oversubscribe -np 3 "$povtrace" "$@" +GD"$work/mpi.debug" +O"$work/mpi/frame" "$scene"
[[ -s $work/one.debug ]] || { echo "FAIL: the scene printed no #debug line"; exit 1; }
diff <(sort "$work/one.debug") <(sort "$work/mpi.debug") || { echo "FAIL: different #debug lines"; exit 1; }
one=$(cd "$work/one" && ls) mpi=$(cd "$work/mpi" && ls)
[[ -n $one ]] || { echo "FAIL: no frame written"; exit 1; }
[[ $one == "$mpi" ]] || { echo "FAIL: different files"; echo "one: $one"; echo "mpi: $mpi"; exit 1; }
for f in $one; do cmp "$work/one/$f" "$work/mpi/$f"; done
echo "same $(echo "$one" | wc -l) frames: $*"
