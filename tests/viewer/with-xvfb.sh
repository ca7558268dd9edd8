#!/usr/bin/env bash
# with-xvfb.sh <command...>: runs the command on a private Xvfb and returns its exit status.
# -displayfd makes Xvfb pick a free display itself, so tests running in parallel cannot collide
# (xvfb-run -a guesses a number and can race).
set -u
dir=$(mktemp -d)
trap 'kill $xvfb 2>/dev/null; rm -rf "$dir"' EXIT
exec 3> "$dir/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp > "$dir/xvfb.log" 2>&1 &
xvfb=$!
exec 3>&-
for _ in $(seq 100); do
  [ -s "$dir/display" ] && break
  sleep 0.1
done
[ -s "$dir/display" ] || { echo "with-xvfb: Xvfb did not start"; cat "$dir/xvfb.log"; exit 1; }
export DISPLAY=":$(head -n1 "$dir/display")"
"$@"
