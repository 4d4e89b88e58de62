#!/usr/bin/env bash
# What accuracy costs in time: build and run tests/bench/accuracy_cost (Release), then draw
# docs/accuracy.svg with gnuplot. Writes docs/accuracy.md and docs/accuracy.svg.
#   bash tests/bench/run_accuracy.sh [--quick]
set -euo pipefail
cd "$(dirname "$0")/../.."
KINERGY_EXTRA_PACKAGES="gnuplot-nox" bash .ci/setup --deps
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build build-bench --target accuracy_cost -j"$(nproc)"
./build-bench/tests/bench/accuracy_cost --out docs --data build-bench "$@"
gnuplot build-bench/accuracy.gp
echo "wrote docs/accuracy.md and docs/accuracy.svg"
