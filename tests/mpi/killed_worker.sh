#!/usr/bin/env bash
# A dead worker is an error, not a hang: kill -9 one worker rank of `mpirun -np 3 povtrace` mid-render; the job
# must end with a non-zero status within 90 s and leave no output file. With SIGNAL=STOP the worker is frozen
# instead (mpirun does not notice that): rank 0's tile deadline must end it (POVTRACE_MPI_TILE_TIMEOUT=15 here:
# with 5 s, the live worker, slowed by a busy machine, missed it first).
# Usage: killed_worker.sh MPIRUN POVTRACE WORK_DIR [KILL|STOP]
set -uo pipefail
# Under AddressSanitizer (scripts/test_sanitized.sh) OpenMPI's start-up allocations are reported as leaks at exit,
# from plugins it has already unloaded, so no suppression can name them: leak checking is off for the ranks here
# (every other test still leak-checks povtrace's code; the sanitizers' other checks stay on).
if [[ -n ${ASAN_OPTIONS:-} ]]; then export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"; fi
mpirun=$1 povtrace=$2 work=$3 signal=${4:-KILL}
mkdir -p "$work"
rm -f "$work/killed.png"
# Twelve reflective spheres under a 9x9 area light, every pixel supersampled: several seconds on two cores.
cat > "$work/slow.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> }
light_source { <-4, 8, -5> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
#declare I = 0;
#while (I < 12)
  sphere { <mod(I, 4) * 1.2 - 1.8, 0.4, div(I, 4) * 1.2 - 1>, 0.4
    pigment { rgb <0.8, 0.4, 0.2> } finish { phong 0.5 reflection 0.2 } }
  #declare I = I + 1;
#end
POV
POVTRACE_MPI_TILE_TIMEOUT=15 "$mpirun" --allow-run-as-root --oversubscribe -x POVTRACE_MPI_TILE_TIMEOUT -np 3 "$povtrace" +W640 +H480 +A0.0 +R3 +WT1 \
  +O"$work/killed.png" "$work/slow.pov" > "$work/killed.log" 2>&1 &
launcher=$!
# The worker with rank 1: a child of mpirun whose environment says OMPI_COMM_WORLD_RANK=1.
victim=""
for _ in $(seq 1 200); do
  for pid in $(pgrep -P "$launcher" 2>/dev/null); do
    if tr '\0' '\n' < "/proc/$pid/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=1'; then victim=$pid; fi
  done
  [[ -n $victim ]] && break
  sleep 0.1
done
if [[ -z $victim ]]; then
  echo "FAIL: no rank-1 process found under mpirun $launcher"; kill -9 "$launcher"; cat "$work/killed.log"; exit 1
fi
sleep 3    # mid-render: the scene is parsed in milliseconds, the render takes several seconds
if ! kill -0 "$launcher" 2>/dev/null; then
  echo "FAIL: the render finished before the kill; the scene is not slow enough here"; cat "$work/killed.log"; exit 1
fi
kill -s "$signal" "$victim"
start=$SECONDS
status=""
while (( SECONDS - start < 90 )); do
  if ! kill -0 "$launcher" 2>/dev/null; then wait "$launcher"; status=$?; break; fi
  sleep 0.2
done
cat "$work/killed.log"
if [[ -z $status ]]; then
  echo "FAIL: mpirun still running 90 s after the worker was killed"; kill -9 "$victim" "$launcher"; exit 1
fi
[[ $signal == STOP ]] && kill -9 "$victim" 2>/dev/null
echo "mpirun exited with $status after $((SECONDS - start)) s"
[[ $status -ne 0 ]] || { echo "FAIL: exit status 0 after a worker died"; exit 1; }
[[ ! -e $work/killed.png ]] || { echo "FAIL: an image was written"; exit 1; }
ls "$work" | grep -q '^killed\.png\.' && { echo "FAIL: a temporary image file was left"; exit 1; }
if [[ $signal == STOP ]] && ! grep -q "rank 1 did not finish tile" "$work/killed.log"; then
  echo "FAIL: no message naming the stuck rank and tile"; exit 1
fi
echo PASS
