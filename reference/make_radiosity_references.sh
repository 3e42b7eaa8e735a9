#!/bin/bash
# Regenerates reference/radiosity/ for every case of reference/radiosity/cases.txt with POV-Ray: one render with
# +WT1 (the reference; POV-Ray's radiosity is reproducible with one thread) and RUNS_WT2 (default 3) renders with
# +WT2 (POV-Ray's own spread: with two threads the result depends on thread timing, docs/issue19-study.md §6),
# their render times (times.csv), the per-scene bars (bars.csv, from scripts/radiosity_compare.py) and README.md.
# Usage: reference/make_radiosity_references.sh [NAME...]   (no names = every case)
#        reference/make_radiosity_references.sh --no-render  (only bars.csv and README.md, from the stored renders)
# Each case's scene folder is copied to a scratch folder and the scene is rendered there, from its own folder, with
# exactly:
#   povray -D -A +W160 +H120 +FE +WTn [switches] +ONAME.wt1.exr (or NAME.wt2-K.exr) SCENE_FILE_NAME
# where [switches] are the case's (cases.txt). Renders run one after the other under `nice`.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
out=$here/radiosity
samples=${POVRAY_SAMPLES:-/usr/share/povray-3.7/scenes}
runs_wt2=${RUNS_WT2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -d "$samples/radiosity" ] || { echo "no POV-Ray sample scenes in $samples (Debian package povray-examples)"; exit 1; }

common=(-D -A +W160 +H120 +FE)
times=$out/times.csv
[ -f "$times" ] || echo "name,output,threads,wall_s,radiosity_s,trace_s,load1_before" > "$times"

# POV-Ray's "(N.NNN seconds)" figure of a "LABEL Time:" line of its statistics, or "" if absent.
pov_seconds() { grep -m1 "^ *$1 Time:" "$2" | sed -n 's/.*(\([0-9.]*\) seconds).*/\1/p'; }

# render NAME SCENE_DIR SCENE_FILE THREADS OUTPUT_NAME SWITCHES... : one timed render into $out, one times.csv row.
render() {
  local name=$1 dir=$2 file=$3 threads=$4 output=$5; shift 5
  local run=$work/$name.$output
  rm -rf "$run"; cp -R "$dir" "$run"
  local load start end
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$EPOCHREALTIME
  if ! (cd "$run" && nice povray "${common[@]}" "+WT$threads" "$@" "+O$out/$output" "$file") > "$run.log" 2>&1; then
    echo "FAIL  $name $output (last lines of POV-Ray's output follow)"; tail -15 "$run.log"; return 1
  fi
  end=$EPOCHREALTIME
  local wall
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  echo "$name,$output,$threads,$wall,$(pov_seconds Radiosity "$run.log"),$(pov_seconds Trace "$run.log"),$load" >> "$times"
  echo "ok    $name $output (${wall} s)"
}

render_cases=1
if [ "${1:-}" = "--no-render" ]; then render_cases=0; shift; fi
failed=0
found=0
[ $render_cases -eq 1 ] && while read -r name scene switches; do
  case $name in ''|'#'*) continue ;; esac
  if [ $# -gt 0 ]; then
    wanted=0
    for n in "$@"; do [ "$n" = "$name" ] && wanted=1; done
    [ $wanted -eq 1 ] || continue
  fi
  found=$((found + 1))
  read -r -a extra <<< "$switches"
  case $scene in
    samples:*) path=$samples/${scene#samples:} ;;
    repo:*) path=$repo/${scene#repo:} ;;
    *) echo "FAIL  $name: scene $scene is neither samples:PATH nor repo:PATH"; failed=1; continue ;;
  esac
  # Drop this case's earlier figures and images, then render it again.
  grep -v "^$name," "$times" > "$work/times" || true
  cp "$work/times" "$times"
  rm -f "$out/$name".wt1.exr "$out/$name".wt2-*.exr
  render "$name" "$(dirname "$path")" "$(basename "$path")" 1 "$name.wt1.exr" "${extra[@]}" || { failed=1; continue; }
  for k in $(seq 1 "$runs_wt2"); do
    render "$name" "$(dirname "$path")" "$(basename "$path")" 2 "$name.wt2-$k.exr" "${extra[@]}" || failed=1
  done
done < "$out/cases.txt"
if [ $render_cases -eq 1 ] && [ $# -gt 0 ] && [ "$found" -ne $# ]; then echo "FAIL  some of the names $* are not in cases.txt"; failed=1; fi

# The bar of each case: the worst PSNR of its +WT2 renders against its +WT1 render (scripts/radiosity_compare.py).
povdiff=${POVDIFF:-$repo/build/povdiff}
spread="(not measured: no povdiff)"
counterparts="(not measured: no povdiff)"
if [ -x "$povdiff" ]; then
  spread=$(python3 "$repo/scripts/radiosity_compare.py" --povdiff "$povdiff" --write-bars "$out/bars.csv" | grep '^|' \
             | cut -d'|' -f2,4 | sed 's/^/|/; s/$/|/') || failed=1
  counterparts=$(python3 "$repo/scripts/radiosity_compare.py" --povdiff "$povdiff" --counterparts) || failed=1
else
  echo "FAIL  no povdiff at $povdiff (build first, or set POVDIFF): bars.csv not rewritten"; failed=1
fi

version=$(povray --version 2>&1 | grep -m1 '^POV-Ray')
cat > "$out/README.md" <<README
# Radiosity reference renders (issue 19)

For each case NAME of \`cases.txt\` (the 13 POV-Ray sample scenes that need nothing but radiosity,
docs/issue19-study.md §8, plus povtrace's own radiosity setting scenes \`scenes/radiosity/radiosity_SETTING.pov\`), made by
\`../make_radiosity_references.sh\` (run it again after changing a case; \`make_radiosity_references.sh NAME...\`
redoes only those):

- \`NAME.wt1.exr\`: POV-Ray's render with one thread (\`+WT1\`). This is **the reference**: POV-Ray's radiosity is
  reproducible with one thread (two +WT1 runs are bit-identical, study §6).
- \`NAME.wt2-1.exr\` … \`NAME.wt2-$runs_wt2.exr\`: $runs_wt2 renders with two threads (\`+WT2\`). With more than one
  thread POV-Ray's radiosity depends on thread timing (which samples exist when a pixel looks, which directions a
  thread's cursor is at), so these show how far POV-Ray itself strays from its own +WT1 image.
- \`times.csv\`: wall-clock seconds of each POV-Ray run (process start to exit, including start-up and parsing),
  POV-Ray's own "Radiosity Time" (pretrace) and "Trace Time" seconds, and the 1-minute load average just before
  the run (the machine has 2 cores and is shared, so the times are indicative).
- \`bars.csv\`: per case, the worst (lowest) PSNR of the +WT2 renders against \`NAME.wt1.exr\`, with that run's mean
  relative difference and RMS, written by \`scripts/radiosity_compare.py --write-bars\`. The CTest tests
  \`radiosity_samples.NAME\` (sample scenes) and \`radiosity_settings.NAME\` (setting scenes), label \`radiosity\`,
  require povtrace's render to be at least as close to the +WT1 reference as the worst +WT2 run is.

- POV-Ray version (first line of \`povray --version\`): \`$version\` (Debian's povray package)
- Scenes: \`samples:PATH\` = Debian's povray-examples, \`/usr/share/povray-3.7/scenes/PATH\` (not copied into this
  repository); \`repo:PATH\` = this repository.
- Command, run in a scratch copy of the scene's folder (so the scene runs from its own folder), for each case:
  \`nice povray -D -A +W160 +H120 +FE +WT1 [switches] +ONAME.wt1.exr SCENE.pov\`, then $runs_wt2 times the same with
  \`+WT2\` and \`+ONAME.wt2-K.exr\`; [switches] are the case's (cases.txt): raddem, an animation, is rendered as the
  single frame \`+K0.5\` (clock 0.5: the red/blue object is turned by 180°; its .ini is not used). No anti-aliasing, 160×120,
  OpenEXR output (POV-Ray writes half float, RGB, zip, linear, unclipped). Debian's /etc/povray/3.7/povray.ini is
  read too (Library_Path entries, Verbose, Bounding_Threshold).
- Generated: $(date -u +%Y-%m-%d), on a shared machine with $(nproc) cores.

Compare a povtrace render with \`python3 scripts/radiosity_compare.py\` (see its --help); it uses the same PSNR as
povdiff (linear light, R, G, B as stored, peak 1.0, no clipping); mean rel = Σ|b − a| / Σ|a| over every channel value.

## Running the tests and the comparison

- \`ctest -L radiosity\` (in build/) runs two tests per case (tests/regression/CMakeLists.txt): povtrace's default
  order (\`radiosity_samples.NAME\`, \`radiosity_settings.NAME\`) must reach the case's bar, and
  \`--radiosity-povray-order\` (\`radiosity_exact.NAME\`, POV-Ray's +WT1 order) the bar and 50 dB. stackerday has only
  the second: its default order is 41.6 dB, below POV-Ray's +WT2 renders (see tests/regression/CMakeLists.txt).
- \`python3 scripts/radiosity_compare.py --povtrace build/povtrace\` renders every case with povtrace (same command,
  from a copy of the scene's folder), prints the table with the verdict and the time ratios POV-Ray/povtrace;
  \`--candidate IMAGE NAME\` or \`--candidate-dir DIR\` compare images made elsewhere; \`--details\` lists every +WT2 run.
- The bar in bars.csv is povdiff's 3-decimal PSNR of the worst +WT2 run minus 0.0005 dB (the lowest the unrounded
  PSNR can be), so that the worst run itself passes its own test (checked: all 99 +WT2 renders pass their case's test
  with \`-DCANDIDATE=\`, every counterpart marked "detects" below fails it).
- The bar is the worst of only $runs_wt2 +WT2 runs: a fourth POV-Ray +WT2 run would itself land below it now and then.

## POV-Ray's own spread (the bars)

The worst of the +WT2 renders against the +WT1 render, per case (bars.csv):

$spread

## Do the setting scenes' tests see their setting?

Each \`scenes/radiosity/radiosity_SETTING.pov\` names a counterpart (\`// counterpart:\`), the same room without that
setting. If the counterpart's +WT1 render is further from the case's +WT1 reference than the case's bar, a renderer
that ignored the setting would fail the case's test (\`radiosity_compare.py --counterparts\`):

$counterparts
README
exit $failed
