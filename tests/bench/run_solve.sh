#!/usr/bin/env bash
# Whole `kinergy solve` processes: against a sympy.physics.mechanics script on the sliding rod,
# and an N-link pendulum's energy problem for N = 2 ... 16 (tests/bench/solve_scaling.py).
# Writes docs/solve_scaling.md.
#   bash tests/bench/run_solve.sh [--max-n N] [--repeats R] [--out FILE]
set -euo pipefail
cd "$(dirname "$0")/../.."
KINERGY_EXTRA_PACKAGES="python3-sympy python3-mpmath" bash .ci/setup --deps
bench="${KINERGY_BENCH_DIR:-build-bench}"
cmake -S . -B "$bench" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build "$bench" --target kinergy_cli -j"$(nproc)"
/usr/bin/python3 tests/bench/solve_scaling.py --kinergy "$bench/kinergy" --command "bash tests/bench/run_solve.sh${*:+ $*}" "$@"
