#!/usr/bin/env bash
# A batch split over processes with GNU parallel (Debian `parallel`), as it would be over machines:
# the requests cut into chunks of 5 lines, each chunk one `kinergy batch`, two at a time, results in
# the requests' order. Each result must equal the serial run's (matched by id; "line" counts within
# a chunk, and so does the "<batch line N>" an error names). Variants of one scene share the first
# one's solution in each process (docs/batch.md): which one is solved in full, and so each
# evaluation's error bound and how each is confirmed, depend on where the chunks are cut; their
# values do not.
#   bash tests/batch/test_parallel.sh KINERGY
set -euo pipefail
cd "$(dirname "$0")/../.."
kinergy="$1"
if ! command -v parallel >/dev/null; then
  echo "test_parallel: GNU parallel is not installed (Debian: parallel); not run"
  exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
i=0
for f in derivations/energy/*.yaml; do
  i=$((i + 1))
  [ "$i" -gt 12 ] && break
  echo "{\"id\": \"$i\", \"scene\": \"$f\"}"
done > "$tmp/requests.jsonl"
# variants of one scene, and a request that fails (it must fail the same way in both runs)
for l in 0.5 1 2 4; do echo "{\"id\": \"rod-$l\", \"scene\": \"derivations/energy/sliding_rod.yaml\", \"set\": {\"l\": \"$l m\"}}"; done >> "$tmp/requests.jsonl"
echo '{"id": "bad", "scene": "derivations/energy/sliding_rod.yaml", "set": {"zz": 1}}' >> "$tmp/requests.jsonl"
"$kinergy" batch "$tmp/requests.jsonl" > "$tmp/serial.jsonl" 2>/dev/null || true
parallel --will-cite --pipe -N 5 -j 2 --keep-order "$kinergy" batch < "$tmp/requests.jsonl" > "$tmp/parallel.jsonl" 2>/dev/null || true
strip() {
  sed -E -e 's/^\{"line": [0-9]+, /{/' -e 's/<batch line [0-9]+>/<batch line>/' -e 's/"evaluation": "double, [^"]*"/"evaluation": "double"/g' \
    -e 's/, "confirmed": \[.*\]\}\}$/}}/' "$1"
}
n=$(wc -l < "$tmp/requests.jsonl")
[ "$(wc -l < "$tmp/parallel.jsonl")" -eq "$n" ] || { echo "test_parallel: $(wc -l < "$tmp/parallel.jsonl") results for $n requests" >&2; exit 1; }
if ! diff <(strip "$tmp/serial.jsonl") <(strip "$tmp/parallel.jsonl") >&2; then
  echo "test_parallel: the parallel run's results differ from the serial run's" >&2
  exit 1
fi
grep -q '"id": "bad", "ok": false' "$tmp/parallel.jsonl" || { echo "test_parallel: the failing request did not fail" >&2; exit 1; }
grep -q '"by": "shared solution"' "$tmp/serial.jsonl" || { echo "test_parallel: no variant shared the rod's solution" >&2; exit 1; }
echo "test_parallel: $n requests in chunks of 5 over 2 processes, the same results as one process"
