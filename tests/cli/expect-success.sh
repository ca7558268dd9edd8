#!/usr/bin/env bash
# expect-success.sh <expectation>... -- <command...>
# Passes when the command exits 0 and every expectation holds afterwards:
#   FILE          FILE exists (it is removed before the command runs, so an old one does not count)
#   FILE=WxH      FILE is an EXR of W x H texels with one 32-bit float channel
#   FILE~REGEX    FILE exists and has a line matching REGEX
#   OUTPUT~REGEX  the command's output (stdout and stderr) has a line matching REGEX
#   "FILE spread MIN", "FILE@WxH+X+Y darker|brighter OTHER@WxH+X+Y MARGIN"
#                 what FILE shows: its luminance varies, or a region of it is darker or brighter than a
#                 region of OTHER (which may be FILE itself). FILE is removed before the command runs, OTHER is not.
# $PENUMBRA_IMAGE_CHECK (tests/support/ImageCheck.cpp) reads and measures the pictures and EXR files.
# The exit status decides alone: CTest's PASS_REGULAR_EXPRESSION would ignore it.
set -u
expectations=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do expectations+=("$1"); shift; done
[ $# -gt 0 ] || { echo "usage: expect-success.sh <expectation>... -- <command...>"; exit 2; }
shift
file_of() { local word=${1%% *}; echo "${word%%[=~@]*}"; }
for e in "${expectations[@]}"; do
  file=$(file_of "$e")
  [ "$file" = OUTPUT ] || rm -f "$file"
done
output=$("$@" 2>&1)
status=$?
echo "$output"
echo "exit status: $status"
[ "$status" -eq 0 ] || { echo "FAIL: the command failed"; exit 1; }
for e in "${expectations[@]}"; do
  file=$(file_of "$e") word=${e%% *}
  if [ "$file" = OUTPUT ]; then
    grep -Eq -- "${e#*~}" <<<"$output" || { echo "FAIL: no line of the output matches '${e#*~}'"; exit 1; }
    continue
  fi
  [ -f "$file" ] || { echo "FAIL: $file was not written"; exit 1; }
  case "$word" in
    *~*)
      grep -Eq -- "${e#*~}" "$file" || { echo "FAIL: no line of $file matches '${e#*~}'"; exit 1; } ;;
    *=*)
      "$PENUMBRA_IMAGE_CHECK" "$file" depth "${e#*=}" || { echo "FAIL: $file is not one float channel of ${e#*=}"; exit 1; } ;;
    *)
      if [ "$word" != "$e" ]; then
        # shellcheck disable=SC2086 # the expectation's words are the checker's arguments
        "$PENUMBRA_IMAGE_CHECK" $e || { echo "FAIL: $e"; exit 1; }
      fi ;;
  esac
done
echo "ok: ${#expectations[@]} expectation(s) hold"
