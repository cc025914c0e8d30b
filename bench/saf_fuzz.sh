#!/usr/bin/env bash
# Robustness bench of the Safety service (SAF-03), never pass/fail in CI:
#  1. the GoogleTest tests of tests/cpp/saf/ built with AddressSanitizer and
#     UndefinedBehaviorSanitizer (g++), run once;
#  2. the libFuzzer target src/saf/fuzz_codec.cpp (clang, -fsanitize=fuzzer,address,undefined)
#     run for RUNS executions (default 1,000,000) from a seed corpus of valid messages.
# Prints the execution count, the crash count and the time. Needs clang with libFuzzer
# (Debian: apt-get install clang; not installed by scripts/setup.sh): without it the script
# says so in one line and exits 3 before step 1. Usage: bash bench/saf_fuzz.sh [RUNS]
# `bash bench/saf_fuzz.sh --sanitize-only` runs step 1 alone (g++ only, no clang needed);
# its exit code is the number of sanitized runs that failed (0: all passed).
set -euo pipefail
cd "$(dirname "$0")/.."
SANITIZE_ONLY=0
if [ "${1:-}" = "--sanitize-only" ]; then SANITIZE_ONLY=1; shift; fi
RUNS=${1:-1000000}
OUT=build/saf-fuzz
mkdir -p "$OUT/corpus" "$OUT/crashes"

# Step 2 needs clang with libFuzzer, which scripts/setup.sh does not install (the test command
# does not need it): check first, so a missing compiler is one line, not a failure after step 1.
CLANG=${CLANG:-$(command -v clang++ || true)}
if [ "$SANITIZE_ONLY" -eq 0 ] && { [ -z "$CLANG" ] || ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
    "$CLANG" -x c++ -fsanitize=fuzzer - -o "$OUT/probe" >/dev/null 2>&1; }; then
  echo "saf_fuzz.sh: clang++ with libFuzzer not found (${CLANG:-no clang++ on PATH}); install it with: apt-get install clang libclang-rt-14-dev (or set CLANG=/path/to/clang++)" >&2
  exit 3
fi

echo "== 1. Safety service tests under ASan + UBSan (g++)"
if [ ! -f build/saf-asan/build.ninja ]; then
  cmake -S . -B build/saf-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DSAFESTATE_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" >/dev/null
fi
TESTS=$(cd tests/cpp/saf && ls test_saf*.cpp | sed 's/\.cpp$//')
# shellcheck disable=SC2086
cmake --build build/saf-asan --target $TESTS saf_demo | grep -vE '^\[[0-9]+/[0-9]+\]' || true
asan_failures=0
for t in $TESTS; do
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "build/saf-asan/src/saf/tests/$t" --gtest_brief=1 >"$OUT/$t.log" 2>&1; then
    echo "FAILED under sanitizers: $t (log: $OUT/$t.log)"; asan_failures=$((asan_failures + 1))
  fi
done
if ! build/saf-asan/src/saf/saf_demo >"$OUT/saf_demo.log" 2>&1; then
  echo "FAILED under sanitizers: saf_demo (log: $OUT/saf_demo.log)"; asan_failures=$((asan_failures + 1))
fi
echo "sanitized runs failed: $asan_failures (tests: $(echo $TESTS | wc -w), plus saf_demo)"
[ "$SANITIZE_ONLY" -eq 1 ] && exit "$asan_failures"

echo "== 2. libFuzzer on the codec and intake ($RUNS executions)"
"$CLANG" -std=c++17 -O1 -g -Iinclude -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  src/saf/codec.cpp src/saf/config.cpp src/saf/inbound_batch.cpp src/saf/safety_service.cpp \
  src/saf/intake.cpp src/saf/estop_extension.cpp src/saf/link_auth.cpp src/saf/sha256.cpp src/saf/source.cpp \
  src/saf/fuzz_codec.cpp -o "$OUT/saf_fuzz_codec"
# Seeds: one valid datagram of each of the nine types (design §10).
printf '\x3c\x01\x00\x00\x01\x00\x00\x00\x01\x00\x01' >"$OUT/corpus/set_estop"
printf '\x3e\x01\x00\x00\x01\x00\x00\x00\x01\x00\x03' >"$OUT/corpus/health_fatal"
printf '\x2d\x01\x00\x00\x01\x00\x00\x00\x01\x00\x00' >"$OUT/corpus/confirm_control"
printf '\x2f\x01\x00\x00\x01\x00\x00\x00\x05\x00\x03\x02\x01\x00\xe1' >"$OUT/corpus/report_control"
printf '\x3b\x01\x00\x00\x01\x00\x00\x00\x01\x00\x02' >"$OUT/corpus/report_subsystem_state"
printf '\x3d\x01\x00\x00\x01\x00\x00\x00\x00\x00' >"$OUT/corpus/query_health"
printf '\x2a\x01\x00\x00\x01\x00\x00\x00\x06\x00\x00\xe1\x03\x02\x01\x00' >"$OUT/corpus/request_control"
printf '\x2c\x01\x00\x00\x01\x00\x00\x00\x00\x00' >"$OUT/corpus/query_control"
printf '\x39\x01\x00\x00\x01\x00\x00\x00\x01\x00\x01' >"$OUT/corpus/set_subsystem_state"
start=$(date +%s)
set +e
"$OUT/saf_fuzz_codec" -runs="$RUNS" -max_len=256 -seed=1 -artifact_prefix="$OUT/crashes/" \
  -print_final_stats=1 "$OUT/corpus" >"$OUT/fuzz.log" 2>&1
rc=$?
set -e
end=$(date +%s)
runs=$(grep -E '^stat::number_of_executed_units' "$OUT/fuzz.log" | awk '{print $2}')
crashes=$(find "$OUT/crashes" -type f | wc -l)
echo "libFuzzer: ${runs:-?} executions, $crashes crashes, exit code $rc, $((end - start)) s (log: $OUT/fuzz.log)"
[ "$rc" -eq 0 ] && [ "$crashes" -eq 0 ] && [ "$asan_failures" -eq 0 ]
