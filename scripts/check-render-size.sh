#!/usr/bin/env bash
# Fails, naming each, where a file of render/ has more than 500 lines or a function defined in a render/ source more
# than 60 (the frame stays a graph of small passes, not one long function); prints the largest of each either way.
# A function is what clang-format puts between a "{" and a "}" in the first column.
set -euo pipefail
cd "$(dirname "$0")/.."
max_file_lines=500 max_function_lines=60
mapfile -t files < <(find render -name '*.cpp' -o -name '*.hpp' | sort)
largest_file=$(wc -l "${files[@]}" | grep -v ' total$' | sort -rn | awk 'NR == 1 { print $2 " (" $1 " lines)" }')
functions=$(for f in "${files[@]}"; do
  awk -v file="$f" '/^\{/ { start = NR; signature = previous }
                    /^\}/ && start { print NR - start + 1, file ":" start, signature; start = 0 }
                    { previous = $0 }' "$f"
done | sort -rn)
echo "check-render-size: largest file: $largest_file; largest function: $(awk 'NR == 1 { print $2 " (" $1 " lines)" }' <<<"$functions")"
failed=0
while read -r lines file; do
  if [ "$lines" -gt "$max_file_lines" ]; then echo "$file: $lines lines, over $max_file_lines" >&2; failed=1; fi
done < <(wc -l "${files[@]}" | grep -v ' total$')
while read -r lines where signature; do
  if [ -n "$lines" ] && [ "$lines" -gt "$max_function_lines" ]; then
    echo "$where: a function of $lines lines, over $max_function_lines: $signature" >&2
    failed=1
  fi
done <<<"$functions"
exit "$failed"
