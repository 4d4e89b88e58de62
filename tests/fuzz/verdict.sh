#!/usr/bin/env bash
# The verdict on a fuzzing run (tests/fuzz/run.sh): exit 0 when it finished clean.
#   bash tests/fuzz/verdict.sh FINDINGS_DIR LOG EXIT_STATUS DONE_LINE_REGEX
# A finding is a crash, a leak, a timeout (-timeout: one input past its limit) or running out of
# memory: libFuzzer's crash-*, leak-*, timeout-*, oom-* artifacts, a non-zero exit, or a log without
# the line a finished run ends with. An input that is merely slow is not a finding: libFuzzer keeps
# it as slow-unit-* when it took 10 s (run.sh sets -report_slow_units past -timeout so none is
# written, and one left here is not judged), and on a loaded machine under the sanitizers a
# 0.2 s input can take that long. So a loaded machine gives the verdict an idle one gives.
set -uo pipefail
dir="$1" log="$2" status="$3" done_line="$4"
findings=$(find "$dir" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) 2>/dev/null | sort | head -5)
if [ -n "$findings" ] || [ "$status" -ne 0 ] || ! grep -qE "$done_line" "$log"; then
  echo "fuzz: the run did not finish clean (exit $status; see $log and $dir${findings:+: }$(echo $findings))" >&2
  exit 1
fi
slow=$(find "$dir" -maxdepth 1 -type f -name 'slow-unit-*' 2>/dev/null | wc -l)
[ "$slow" -gt 0 ] && echo "fuzz: $slow slow input(s) kept in $dir (slow is not a finding: each finished within -timeout)"
exit 0
