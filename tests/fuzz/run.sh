#!/usr/bin/env bash
# Fuzz load -> build -> solve with libFuzzer (clang, AddressSanitizer, UndefinedBehaviorSanitizer),
# seeded from every scene of derivations/ and tests/, with the format's keys as a dictionary.
#   bash tests/fuzz/run.sh [SECONDS] [RUNS] [SEED] [JOBS]
#   (defaults: 60 s, no limit on runs, a random seed, one process; JOBS > 1: libFuzzer's fork mode,
#   JOBS processes sharing one corpus, RUNS counted over all of them)
# SECONDS 0: no time limit. With RUNS, SEED and no time limit the run is the same every time (the
# test command uses one such short run); it runs with address randomisation off where that is
# allowed, since GiNaC's forms (and so the coverage) depend on addresses.
# Builds in build-fuzz/. Exit 0 when no input crashed, leaked, ran out of memory or time (a slow
# input that finished within -timeout is not a finding: a loaded machine gives the same verdict).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
runs="${2:--1}"
seed="${3:-0}"
jobs="${4:-1}"
command -v clang++ >/dev/null || { echo "fuzz: clang++ is not installed (Debian: clang, libclang-rt-14-dev)" >&2; exit 2; }
# -gline-tables-only: a finding's stack names files and lines, and the build takes less time than
# with full debug information (the test command builds this directory from nothing); the code is
# the same either way
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" \
  -DKINERGY_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target kinergy_fuzz >/dev/null
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
find derivations tests/data tests/stability -name '*.yaml' -exec cp {} "$corpus" \; 2>/dev/null || true
cp tests/fuzz/regressions/* "$corpus" 2>/dev/null || true  # inputs that once failed: seeds too
# the scenes' own files are seeds; findings go to build-fuzz/findings (keep each one, once fixed, in
# tests/fuzz/regressions: a test runs them all)
rm -rf build-fuzz/findings && mkdir -p build-fuzz/findings
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitize.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
export KINERGY_CACHE="$corpus/cache"
norandom=()
setarch "$(uname -m)" -R true 2>/dev/null && norandom=(setarch "$(uname -m)" -R)
log=build-fuzz/fuzz.log
status=0
fork=()
done_line="^Done [0-9]* runs"
if [ "$jobs" -gt 1 ]; then
  fork=(-fork="$jobs")
  done_line="^INFO: (fuzzed for [0-9]* iterations|exiting: 0 time)"
fi
"${norandom[@]}" ./build-fuzz/tests/fuzz/kinergy_fuzz "$corpus" -dict=tests/fuzz/scene.dict -max_total_time="$seconds" \
  -runs="$runs" -seed="$seed" -timeout=60 -report_slow_units=100000 -rss_limit_mb=4096 -max_len=8192 -print_final_stats=1 "${fork[@]}" \
  -artifact_prefix=build-fuzz/findings/ >"$log" 2>&1 || status=$?
grep -E "^(#[0-9]+ +(DONE|INITED)|Done [0-9]+ runs|INFO: (fuzzed for|exiting)|stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY|kinergy_fuzz:|.*(crash|leak|timeout|oom)-)" "$log" || true
[ "$jobs" -gt 1 ] && grep -E "^#[0-9]+:" "$log" | tail -1
bash tests/fuzz/verdict.sh build-fuzz/findings "$log" "$status" "$done_line"
