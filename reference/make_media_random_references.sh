#!/bin/bash
# Regenerates reference/media_random/ for every scenes/media_random/NAME.pov with POV-Ray: one render with +WT1 (the
# reference: POV-Ray's random media sampling, method 1, jitter, or extra samples past the minimum, draws from a
# per-thread random sequence, so it is reproducible with one thread only) and RUNS_WT2 (default 3) renders with
# +WT2 (POV-Ray's own spread: which pixels a thread renders, and so which random numbers a pixel gets, depends on
# thread timing), their render times (times.csv) and README.md with the spread.
# Usage: reference/make_media_random_references.sh [NAME...]   (no names = every scene of scenes/media_random/)
#        reference/make_media_random_references.sh --no-render (only README.md, from the stored renders)
#        KIND=photons_random reference/make_media_random_references.sh [...]: the same for scenes/photons_random/
#        (photon maps shot by several threads, reference/photons_random/).
# Each scene is rendered from its own folder, scenes/media_random/ (its includes are relative to it), with exactly:
#   nice povray -D -A +W320 +H240 +FE +WTn [switches] +O../../reference/media_random/NAME.exr (or NAME.wt2_K.exr) NAME.pov
# where [switches] are those of a "// switches: …" line in the scene, if any. Renders run one after the other.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
kind=${KIND:-media_random}
case "$kind" in media_random|photons_random) ;; *) echo "KIND must be media_random or photons_random"; exit 2 ;; esac
scenes=$repo/scenes/$kind
out=$here/$kind
runs_wt2=${RUNS_WT2:-3}
povdiff=${POVDIFF:-$repo/build/povdiff}
log_dir=$(mktemp -d)
trap 'rm -rf "$log_dir"' EXIT
mkdir -p "$out"

common=(-D -A +W320 +H240 +FE)
times=$out/times.csv
[ -f "$times" ] || echo "name,output,threads,wall_s,trace_s,load1_before" > "$times"

# render NAME THREADS OUTPUT_NAME SWITCHES... : one timed render into $out, one times.csv row.
render() {
  local name=$1 threads=$2 output=$3; shift 3
  local log=$log_dir/$output.log load start end wall trace
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$EPOCHREALTIME
  if ! (cd "$scenes" && nice povray "${common[@]}" "+WT$threads" "$@" "+O$out/$output" "$name.pov") > "$log" 2>&1; then
    echo "FAIL  $name $output (last lines of POV-Ray's output follow)"; tail -15 "$log"; return 1
  fi
  end=$EPOCHREALTIME
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  trace=$(grep -m1 '^ *Trace Time:' "$log" | sed -n 's/.*(\([0-9.]*\) seconds).*/\1/p')
  echo "$name,$output,$threads,$wall,$trace,$load" >> "$times"
  echo "ok    $name $output (${wall} s)"
}

render_scenes=1
if [ "${1:-}" = "--no-render" ]; then render_scenes=0; shift; fi
if [ $# -gt 0 ]; then names=("$@"); else
  names=()
  for f in "$scenes"/*.pov; do names+=("$(basename "${f%.pov}")"); done
fi

failed=0
if [ $render_scenes -eq 1 ]; then
  for n in "${names[@]}"; do
    [ -f "$scenes/$n.pov" ] || { echo "FAIL  no scene $scenes/$n.pov"; failed=1; continue; }
    read -r -a extra <<< "$(grep -m1 '^// switches:' "$scenes/$n.pov" | sed 's|^// switches:||')"
    # Drop this scene's earlier figures and images, then render it again.
    grep -v "^$n," "$times" > "$log_dir/times" || true
    cp "$log_dir/times" "$times"
    rm -f "$out/$n".exr "$out/$n".wt2_*.exr
    render "$n" 1 "$n.exr" "${extra[@]}" || { failed=1; continue; }
    for k in $(seq 1 "$runs_wt2"); do
      render "$n" 2 "$n.wt2_$k.exr" "${extra[@]}" || failed=1
    done
  done
fi

# POV-Ray's spread: PSNR (povdiff: linear values as stored, peak 1.0) of each +WT2 render against the +WT1
# reference, and between the +WT2 renders; the worst of each, and the worst run's share of pixels off by > 1/255.
# (povdiff exits 1 when the images are outside its default tolerance: not an error here.)
psnr() { { "$povdiff" "$1" "$2" || true; } | tail -1 | sed -n 's/.* psnr=\([^ ]*\) .*/\1/p'; }
share() { { "$povdiff" "$1" "$2" || true; } | tail -1 | sed -n 's/.* share=\([^ ]*\) .*/\1/p'; }
if [ -x "$povdiff" ]; then
  spread="| scene | worst +WT2 vs +WT1 PSNR (dB) | its pixels off > 1/255 | worst +WT2 vs +WT2 PSNR (dB) | +WT1 render (s) |
| --- | --- | --- | --- | --- |"
  for f in "$scenes"/*.pov; do
    n=$(basename "${f%.pov}")
    [ -f "$out/$n.exr" ] || continue
    worst=""; worst_share=""; worst_pair=""
    for a in "$out/$n".wt2_*.exr; do
      p=$(psnr "$out/$n.exr" "$a")
      if [ -z "$worst" ] || awk -v p="$p" -v w="$worst" 'BEGIN { exit !(p < w) }'; then
        worst=$p; worst_share=$(share "$out/$n.exr" "$a")
      fi
      for b in "$out/$n".wt2_*.exr; do
        [[ "$a" < "$b" ]] || continue
        p=$(psnr "$a" "$b")
        if [ -z "$worst_pair" ] || awk -v p="$p" -v w="$worst_pair" 'BEGIN { exit !(p < w) }'; then worst_pair=$p; fi
      done
    done
    wall=$(grep "^$n,$n.exr," "$times" | cut -d, -f4)
    spread="$spread
| $n | $worst | $(awk -v s="$worst_share" 'BEGIN { printf "%.1f %%", 100 * s }') | ${worst_pair:-–} | $wall |"
  done
else
  echo "FAIL  no povdiff at $povdiff (build first, or set POVDIFF): README.md has no spread"; failed=1
  spread="(not measured: no povdiff)"
fi

version=$(povray --version 2>&1 | grep -m1 '^POV-Ray')
if [ "$kind" = photons_random ]; then
  title="Photon reference renders that are random in POV-Ray (issue 20)"
  why="These scenes shoot photons from more than one light or at more than one target. POV-Ray
  hands the light × target units to its shooting threads in turn, each thread jittering its photons from its own run
  through a fixed table of random numbers: one thread gives the same map every time, two threads another one (which
  units a thread gets depends on timing). povtrace shoots POV-Ray's one-thread map with any number of threads."
  folder=photons_random
  includes=""
else
  title="Media reference renders that are random in POV-Ray (issue 20)"
  why="These scenes use media
  sampling that draws random numbers (method 1; jitter > 0 with method 2 or 3; samples MIN,MAX with MAX > MIN, whose
  extra samples go at random places with method 1 and 2 alike: media.cpp ComputeMediaRegularSampling). POV-Ray takes
  them from a fixed sequence per render thread, so one thread gives the same image every time (checked: two +WT1
  renders are identical), but with two threads which pixels a thread renders, and so which numbers a pixel gets,
  depends on thread timing."
  folder=media_random
  includes=' (the scenes include `../media_sampling.inc`)'
fi
cat > "$out/README.md" <<README
# $title

For each scene \`../../scenes/$folder/NAME.pov\`, made by \`KIND=$folder ../make_media_random_references.sh\` (run it
again after changing a scene; with NAME... it redoes only those):

- \`NAME.exr\`: POV-Ray's render with one thread (\`+WT1\`). This is **the reference**. $why
- \`NAME.wt2_1.exr\` … \`NAME.wt2_K.exr\`: renders with two threads (\`+WT2\`), POV-Ray's own spread: 3 per scene
  (RUNS_WT2), 9 for media_method1_confidence, whose three first runs spread less than POV-Ray's runs do (six more
  runs reached 33.15 to 33.42 dB against the reference, the first three 33.32 to 33.38).
- \`times.csv\`: wall-clock seconds of each POV-Ray run (start to exit), POV-Ray's "Trace Time" and the 1-minute load
  average just before the run (the machine is shared: the times are indicative).

- POV-Ray version (first line of \`povray --version\`): \`$version\` (Debian's povray package)
- Command, run in \`scenes/$folder/\`$includes, for each scene:
  \`nice povray -D -A +W320 +H240 +FE +WT1 [switches] +O…/NAME.exr NAME.pov\`, then K times the same with
  \`+WT2\` and \`NAME.wt2_K.exr\`; [switches] are those of a \`// switches: …\` line in the scene, if any. No
  anti-aliasing, 320×240, OpenEXR (half float, RGB, zip, linear, unclipped). Debian's /etc/povray/3.7/povray.ini is
  read too (Library_Path entries, Verbose, Bounding_Threshold).
- Generated: $(date -u +%Y-%m-%d), on a shared machine with $(nproc) cores.

## POV-Ray's own spread

PSNR as povdiff computes it (linear values as stored, peak 1.0). A renderer that matches POV-Ray's sampling but
not its random numbers can expect to land about as far from \`NAME.exr\` as the +WT2 renders do:

$spread
README
exit $failed
