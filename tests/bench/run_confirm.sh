#!/usr/bin/env bash
# What confirmation costs: every derivation's `kinergy solve` with and without --no-confirm,
# alternated (tests/bench/confirm_cost.py). Writes docs/confirm.md.
#   bash tests/bench/run_confirm.sh [--repeats R] [--out FILE]
set -euo pipefail
cd "$(dirname "$0")/../.."
bash .ci/setup --deps
bench="${KINERGY_BENCH_DIR:-build-bench}"
cmake -S . -B "$bench" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build "$bench" --target kinergy_cli -j"$(nproc)"
/usr/bin/python3 tests/bench/confirm_cost.py --kinergy "$bench/kinergy" --command "bash tests/bench/run_confirm.sh${*:+ $*}" "$@"
