#!/usr/bin/env bash
# Fuzzes with libFuzzer for a bounded time: scripts/fuzz.sh [seconds] (default 60), two thirds of it on the SDL
# front end (fuzz/povtrace_parse_fuzzer), one third on the whole pipeline at 8×6 (fuzz/povtrace_render_fuzzer,
# which also fails on a non-finite pixel). Builds them with clang (ASan + UBSan, -DPOVTRACE_FUZZ=ON) in build-fuzz/, seeds the corpus
# with scenes/*.pov (copied at run time) and runs it with a dictionary of SDL keywords made from
# parser/lexing/reserved_words.cpp. Exits non-zero on a finding — a crash, a sanitizer report, an exception other than
# ParseError, a timeout or running out of memory — and leaves the input that caused it in build-fuzz/findings/.
# Reproduce one with: build-fuzz/fuzz/povtrace_parse_fuzzer (or povtrace_render_fuzzer) build-fuzz/findings/<file>
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
out="$root/build-fuzz"
cmake -S "$root" -B "$out" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOVTRACE_FUZZ=ON \
  -DBUILD_TESTING=OFF >/dev/null
cmake --build "$out" --target povtrace_parse_fuzzer povtrace_render_fuzzer -j"$(nproc)"

corpus="$out/corpus"          # grows from run to run on this machine
findings="$out/findings"
mkdir -p "$corpus" "$findings"
cp "$root"/scenes/*.pov "$corpus"/
dict="$out/sdl.dict"
{
  grep -o '^    "[a-z_0-9]*",$' "$root/parser/lexing/reserved_words.cpp" | tr -d ' ,'
  for d in declare local undef include if ifdef ifndef else elseif end while for macro switch case range break \
           default debug warning error version fopen fclose read write; do
    echo "\"#$d\""
  done
  printf '"%s"\n' '{' '}' '(' ')' '<' '>' '[' ']' '=' ';' ',' '.' '\"' '/*' '*/' '//'
} >"$dict"

# #fopen/#write may create files next to the scene, which for this in-memory scene is the working directory:
# give the run a scratch directory of its own.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
run_target() {   # run_target NAME SECONDS
  local name=$1 time=$2 status=0
  echo "fuzz: running $name for ${time}s (corpus $corpus)" >&2
  "$out/fuzz/$name" -max_total_time="$time" -timeout=20 -rss_limit_mb=2048 -max_len=4096 \
    -dict="$dict" -artifact_prefix="$findings/" -print_final_stats=1 "$corpus" 2>"$out/$name.log" || status=$?
  if ((status != 0)); then
    tail -n 60 "$out/$name.log" >&2
    echo "fuzz: FINDING in $name (exit $status); the input is in $findings/, the log in $out/$name.log" >&2
    exit 1
  fi
  grep -E '^Done|^stat::' "$out/$name.log" >&2 || true
}
render_seconds=$((seconds / 3))
run_target povtrace_parse_fuzzer $((seconds - render_seconds))
run_target povtrace_render_fuzzer "$render_seconds"
echo "fuzz: no findings in ${seconds}s" >&2
