#!/usr/bin/env bash
# viewer-screenshot.sh <penumbra> <compare-screenshots> <configuration> <output folder>
# Runs `penumbra view` under its own Xvfb (validation layer / GL debug output on: any message
# makes the viewer exit non-zero), once without and once with the panel, and checks
#  - the screenshot without the panel against `penumbra render` of the same scene, camera and
#    size: same orientation and shadows, PSNR >= 60 dB (the backends' lit parity bound);
#  - the screenshot with the panel differs from it, and only where the panel is (x < 380).
set -euo pipefail
penumbra=$1 compare=$2 configuration=$3 out=$4
size_w=640 size_h=360
rm -rf "$out"
mkdir -p "$out"

# -displayfd makes Xvfb choose a free display itself, so parallel tests cannot collide.
exec 3> "$out/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp > "$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  [ -s "$out/display" ] && break
  sleep 0.1
done
[ -s "$out/display" ] || { echo "FAIL: Xvfb did not start"; cat "$out/xvfb.log"; exit 1; }
export DISPLAY=":$(head -n1 "$out/display")"
echo "Xvfb on $DISPLAY"

view=("$penumbra" view --backend "$configuration" --scene test --size "${size_w}x${size_h}" --frames 4)
"${view[@]}" --no-ui --screenshot "$out/view.png"
"${view[@]}" --screenshot "$out/view-ui.png"
"$penumbra" render -c "$configuration" --scene test --width $size_w --height $size_h -o "$out/render"

"$compare" scene "$out/render/lit.png" "$out/view.png" 60
"$compare" panel "$out/view.png" "$out/view-ui.png" 380
