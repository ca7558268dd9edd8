#!/usr/bin/env bash
# Fails, naming each file, where clang-format (.clang-format) would change a C++ source; `make format` fixes them.
# With --fix, formats them in place instead. One clang-format process per core for all the files: a process per file
# cost a hundred times more than the formatting.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -d .git ] || [ -f .git ]; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find . -path ./build\* -prune -o \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
jobs=$(nproc)
per_process=$(( (${#files[@]} + jobs - 1) / jobs ))
if [ "${1:-}" = "--fix" ]; then
  printf '%s\0' "${files[@]}" | xargs -0 -P "$jobs" -n "$per_process" clang-format -i
  exit 0
fi
# --dry-run -Werror reports each change as "FILE:LINE:COL: error: code should be clang-formatted"; xargs exits 123
# when an invocation exited 1 to 125. Any other failure (clang-format missing, a crash) is reported as it is.
status=0
report=$(printf '%s\0' "${files[@]}" | xargs -0 -P "$jobs" -n "$per_process" clang-format --dry-run -Werror 2>&1) ||
  status=$?
mapfile -t unformatted < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"$report" | sort -u)
if [ "$status" -ne 0 ] && { [ "$status" -ne 123 ] || [ ${#unformatted[@]} -eq 0 ]; }; then
  printf 'check-format: clang-format failed (exit %d):\n%s\n' "$status" "$report" >&2
  exit 1
fi
if [ ${#unformatted[@]} -gt 0 ]; then
  printf 'check-format: %d file(s) not formatted as .clang-format says (make format fixes them):\n' "${#unformatted[@]}" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
