#!/usr/bin/env bash
# The fuzzing run's verdict (tests/fuzz/verdict.sh) on made-up runs: a slow input alone passes; a
# crash, leak, timeout or out-of-memory artifact, a non-zero exit or an unfinished log fails.
set -uo pipefail
verdict="$(dirname "$0")/verdict.sh"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
done_line="^Done [0-9]* runs"
printf '#2\tINITED\nDone 1200 runs in 90 second(s)\n' >"$t/done.log"
printf '#2\tINITED\n' >"$t/cut.log"
fail=0
check() {  # expected-exit description dir log status
  local want="$1" what="$2"
  bash "$verdict" "$3" "$4" "$5" "$done_line" >/dev/null 2>&1
  local got=$?
  if [ "$got" -ne "$want" ]; then echo "FAIL: $what: exit $got, expected $want"; fail=1; else echo "ok: $what"; fi
}
mkdir "$t/clean" "$t/slow" "$t/crash" "$t/leak" "$t/timeout" "$t/oom"
touch "$t/slow/slow-unit-0123abcd" "$t/crash/crash-0123abcd" "$t/leak/leak-0123abcd" "$t/timeout/timeout-0123abcd" "$t/oom/oom-0123abcd"
check 0 "a clean run" "$t/clean" "$t/done.log" 0
check 0 "a slow input alone" "$t/slow" "$t/done.log" 0
check 1 "a crash" "$t/crash" "$t/done.log" 0
check 1 "a leak" "$t/leak" "$t/done.log" 0
check 1 "a timeout" "$t/timeout" "$t/done.log" 0
check 1 "out of memory" "$t/oom" "$t/done.log" 0
check 1 "a non-zero exit" "$t/clean" "$t/done.log" 77
check 1 "a run that did not finish" "$t/clean" "$t/cut.log" 0
exit $fail
