#!/usr/bin/env bash
# expect-failure.sh <regex> <file-that-must-not-exist> <command...>
# Passes when the command exits non-zero, prints a line matching <regex>, does not crash
# (no signal exit) and leaves no output file behind.
set -u
regex=$1 file=$2
shift 2
output=$("$@" 2>&1)
status=$?
echo "$output"
echo "exit status: $status"
[ "$status" -ne 0 ] || { echo "FAIL: the command succeeded"; exit 1; }
[ "$status" -lt 128 ] || { echo "FAIL: the command died from a signal"; exit 1; }
grep -Eq -- "$regex" <<<"$output" || { echo "FAIL: no message matching '$regex'"; exit 1; }
[ ! -e "$file" ] || { echo "FAIL: $file was written"; exit 1; }
ls "$(dirname "$file")" 2>/dev/null | grep -q partial && { echo "FAIL: a partial file was left"; exit 1; }
exit 0
