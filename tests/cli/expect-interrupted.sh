#!/usr/bin/env bash
# expect-interrupted.sh <regex> <file-that-must-not-exist> <command...>
# Starts the command, sends it SIGINT once its output has a line matching <regex> (it is then inside its long
# part: tracing rows, drawing frames), and passes when it exits with status 130 (128 + SIGINT), says it was
# interrupted, and leaves neither <file> nor a temporary ".partial-" file beside it.
set -u
regex=$1 file=$2
shift 2
log=$(mktemp)
trap 'rm -f "$log"' EXIT
rm -f "$file"
# A background job of a non-interactive shell starts with SIGINT ignored (POSIX.1-2017 "sh", "Asynchronous
# Lists"); the tool installs its own handler, which replaces that.
"$@" >"$log" 2>&1 &
pid=$!
for _ in $(seq 1 1200); do
  grep -Eq -- "$regex" "$log" && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
grep -Eq -- "$regex" "$log" || { tail -c 1000 "$log"; echo; echo "FAIL: no output matching '$regex' before the command ended"; exit 1; }
kill -INT "$pid"
wait "$pid"
status=$?
tail -c 1000 "$log"; echo
echo "exit status: $status"
[ "$status" -eq 130 ] || { echo "FAIL: expected exit status 130 (SIGINT)"; exit 1; }
grep -q "interrupted by SIGINT" "$log" || { echo "FAIL: no 'interrupted by SIGINT' message"; exit 1; }
[ ! -e "$file" ] || { echo "FAIL: $file was written"; exit 1; }
ls "$(dirname "$file")" 2>/dev/null | grep -q partial && { echo "FAIL: a partial file was left"; exit 1; }
exit 0
