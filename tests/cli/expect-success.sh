#!/usr/bin/env bash
# expect-success.sh <expectation>... -- <command...>
# Passes when the command exits 0 and every expectation holds afterwards:
#   FILE          FILE exists (it is removed before the command runs, so an old one does not count)
#   FILE=WxH      FILE is an EXR of W x H texels with one 32-bit float channel (iinfo from openimageio-tools)
#   FILE~REGEX    FILE exists and has a line matching REGEX
set -u
expectations=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do expectations+=("$1"); shift; done
[ $# -gt 0 ] || { echo "usage: expect-success.sh <expectation>... -- <command...>"; exit 2; }
shift
for e in "${expectations[@]}"; do rm -f "${e%%[=~]*}"; done
"$@"
status=$?
echo "exit status: $status"
[ "$status" -eq 0 ] || { echo "FAIL: the command failed"; exit 1; }
for e in "${expectations[@]}"; do
  file=${e%%[=~]*}
  [ -f "$file" ] || { echo "FAIL: $file was not written"; exit 1; }
  case "$e" in
    *=*)
      size=${e#*=}
      info=$(iinfo -v "$file" 2>&1)
      grep -Eq -- "^$file : +${size%x*} x +${size#*x}, 1 channel, float openexr" <<<"$info" \
        || { echo "FAIL: $file is not one float channel of $size: $info"; exit 1; } ;;
    *~*)
      grep -Eq -- "${e#*~}" "$file" || { echo "FAIL: no line of $file matches '${e#*~}'"; exit 1; } ;;
  esac
done
echo "ok: ${#expectations[@]} expectation(s) hold"
