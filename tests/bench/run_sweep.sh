#!/usr/bin/env bash
# Sweeps at the speed of the closed form (issue 30): a 1000 × 1000 sweep of the sliding rod
# against one whole `kinergy solve` of it (confirmation on, as a user gets it), side by side in
# one run, each measured REPEATS times (default 5, interleaved) and the median taken; the same
# sweep solved at every point (--per-point) over 1000 points; and a sweep whose valid region ends
# inside the grid (theta2 past 180°: the rod does not get there). Writes the table between the
# bench markers of docs/batch.md.
#   bash tests/bench/run_sweep.sh [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/../.."
repeats="${1:-5}"
cmake -S . -B build >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rod=derivations/energy/sliding_rod.yaml
k=./build/kinergy
# seconds one command takes (its output to $tmp)
timed() {
  local t0 t1
  t0=$(date +%s.%N)
  "$@" > "$tmp/out" 2> "$tmp/err"
  t1=$(date +%s.%N)
  echo "$t1 - $t0" | bc -l
}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
: > "$tmp/solve"; : > "$tmp/sweep"; : > "$tmp/ends"; : > "$tmp/each"
for r in $(seq "$repeats"); do
  timed $k solve "$rod" >> "$tmp/solve"
  timed $k sweep "$rod" --set l=0.5..2:1000 --set theta2=30..90:1000 --csv "$tmp/sweep.csv" >> "$tmp/sweep"
  sweep_note=$(tail -1 "$tmp/err")
  timed $k sweep "$rod" --set l=0.5..2:1000 --set theta2=30..270:1000 --csv "$tmp/ends.csv" >> "$tmp/ends"
  ends_note=$(tail -1 "$tmp/err")
  timed $k sweep "$rod" --set l=0.5..2:40 --set theta2=30..90:25 --per-point --csv "$tmp/each.csv" >> "$tmp/each"
done
solve=$(median < "$tmp/solve")
sweep=$(median < "$tmp/sweep")
ends=$(median < "$tmp/ends")
each=$(median < "$tmp/each")
rows=$(($(wc -l < "$tmp/sweep.csv") - 1))
ratio=$(echo "$sweep / $solve" | bc -l)
met=$(echo "$ratio <= 30" | bc -l)
table=$(cat <<TABLE
<!-- bench:sweep -->
Measured $(date -u +%Y-%m-%d) on $(nproc) cores ($(uname -m)), by \`bash tests/bench/run_sweep.sh $repeats\` (medians of $repeats, interleaved):

| what | points | seconds | × one solve | target |
| --- | --- | --- | --- | --- |
| one \`kinergy solve\` of the sliding rod (confirmed by simulation) | 1 | $(printf %.3f "$solve") | 1 | — |
| \`kinergy sweep\` l = 0.5..2 m × theta2 = 30..90°, 1000 × 1000, CSV to a file | $rows | $(printf %.3f "$sweep") | $(printf %.1f "$ratio") | ≤ 30: $( [ "$met" = 1 ] && echo met || echo "**not met**") |
| the same to theta2 = 270° (past 180° no solution), 1000 × 1000 | 1000000 | $(printf %.3f "$ends") | $(printf %.1f "$(echo "$ends / $solve" | bc -l)") | — |
| \`--per-point\` (solved at each point), 40 × 25 | 1000 | $(printf %.3f "$each") | $(printf %.1f "$(echo "$each / $solve" | bc -l)") | — |

- 30..90°: $sweep_note
- 30..270°: $ends_note
<!-- /bench:sweep -->
TABLE
)
python3 tests/bench/put_table.py docs/batch.md sweep "## Over several processes or machines" "$table"
echo "$table"
