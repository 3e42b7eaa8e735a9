#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (g++, Debug with -O1: the tests run several
# times faster than at -O0 and the sanitizers see the same code) in build-asan/
# Any sanitizer report fails the test that triggers it (UBSan is made fatal through UBSAN_OPTIONS). g++ leaves
# float-cast-overflow out of -fsanitize=undefined: it is added, since SDL values reach integer conversions.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
out="$root/build-asan"
cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="-O1 -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer" >/dev/null
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
cmake --build "$out" -j"$(nproc)"
# Sanitized frames are several times larger: give deep-but-legal nesting (300 levels in the tests) the stack it
# needs; the parser's own stack check still refuses what does not fit.
ulimit -s 65536 2>/dev/null || ulimit -s "$(ulimit -H -s)" 2>/dev/null || true
cd "$out"
ctest --output-on-failure -j"$(nproc)"
