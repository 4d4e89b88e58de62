#!/usr/bin/env bash
# Batch throughput (issues 16, 30): every derivation solved REPEATS times (default 3) in one
# `kinergy batch` process, against one `kinergy solve --json` process per scene, side by side in
# one run; 10^5 variants of the sliding rod (its length and angle) in one `kinergy batch` process;
# and both banks on a Dask LocalCluster of 1 and of 2 worker processes. Writes the table between
# the bench markers of docs/batch.md.
#   bash tests/bench/run_batch.sh [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/../.."
repeats="${1:-3}"
cmake -S . -B build >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in $(seq "$repeats"); do
  for f in derivations/*/*.yaml; do echo "{\"scene\": \"$f\"}"; done
done > "$tmp/requests.jsonl"
n=$(wc -l < "$tmp/requests.jsonl")
./build/kinergy batch "$tmp/requests.jsonl" > /dev/null 2>&1  # warm the evaluator cache
t0=$(date +%s.%N)
./build/kinergy batch "$tmp/requests.jsonl" > /dev/null 2>&1
t1=$(date +%s.%N)
for r in $(seq "$repeats"); do
  for f in derivations/*/*.yaml; do ./build/kinergy solve --json "$f" > /dev/null; done
done
t2=$(date +%s.%N)
# variants of one scene: they share its solution where it holds
nv=100000
awk -v n=$nv 'BEGIN { for (i = 0; i < n; i++) printf "{\"id\": %d, \"scene\": \"derivations/energy/sliding_rod.yaml\", \"set\": {\"l\": \"%.6f m\", \"theta2\": \"%.5f deg\"}}\n", i, 0.5 + 1.5 * (i % 1000) / 999, 20 + 150 * int(i / 1000) / (n / 1000) }' > "$tmp/variants.jsonl"
t3=$(date +%s.%N)
./build/kinergy batch "$tmp/variants.jsonl" > "$tmp/variants.out" 2>&1
t4=$(date +%s.%N)
shared=$(grep -c '"by": "shared solution"' "$tmp/variants.out" || true)
variants=$(echo "$t4 - $t3" | bc -l)
vrate=$(echo "$nv / $variants" | bc -l)
vmet=$(echo "$vrate >= 100000" | bc -l)
batch=$(echo "$t1 - $t0" | bc -l)
procs=$(echo "$t2 - $t1" | bc -l)
rate=$(echo "$n / $batch" | bc -l)
read -r d1 d2 tasks v1 v2 vn < <(PYTHONPATH="$PWD/build/python" /usr/bin/python3 tests/bench/batch_scaling.py "$PWD" "$repeats" "$nv" 2>/dev/null)
met=$(echo "$rate >= 100" | bc -l)
table=$(cat <<TABLE
<!-- bench:batch -->
Measured $(date -u +%Y-%m-%d) on $(nproc) cores ($(uname -m)), by \`bash tests/bench/run_batch.sh $repeats\`:

| what | requests | seconds | a second | target |
| --- | --- | --- | --- | --- |
| one \`kinergy batch\` process | $n | $(printf %.2f "$batch") | $(printf %.1f "$rate") | ≥ 100 a core: $( [ "$met" = 1 ] && echo met || echo "**not met**") |
| one \`kinergy solve --json\` process a scene | $n | $(printf %.2f "$procs") | $(printf %.1f "$(echo "$n / $procs" | bc -l)") | — |
| Dask LocalCluster, 1 worker process | $tasks | $(printf %.2f "$d1") | $(printf %.1f "$(echo "$tasks / $d1" | bc -l)") | — |
| Dask LocalCluster, 2 worker processes | $tasks | $(printf %.2f "$d2") | $(printf %.1f "$(echo "$tasks / $d2" | bc -l)") | scaling 1 → 2: $(printf %.2f "$(echo "$d1 / $d2" | bc -l)")× |
| variants of the sliding rod (l, theta2), one \`kinergy batch\` process ($shared shared the first's solution) | $nv | $(printf %.2f "$variants") | $(printf %.0f "$vrate") | ≥ 10⁵: $( [ "$vmet" = 1 ] && echo met || echo "**not met**") |
| the same variants, Dask LocalCluster, 1 worker process (\`kinergy.batch\`, 10⁴ a task) | $vn | $(printf %.2f "$v1") | $(printf %.0f "$(echo "$vn / $v1" | bc -l)") | — |
| the same variants, Dask LocalCluster, 2 worker processes | $vn | $(printf %.2f "$v2") | $(printf %.0f "$(echo "$vn / $v2" | bc -l)") | scaling 1 → 2: $(printf %.2f "$(echo "$v1 / $v2" | bc -l)")× |
<!-- /bench:batch -->
TABLE
)
python3 tests/bench/put_table.py docs/batch.md batch "## Where the time of distinct scenes goes" "$table"
echo "$table"
