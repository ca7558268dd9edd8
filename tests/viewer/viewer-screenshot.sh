#!/usr/bin/env bash
# viewer-screenshot.sh <penumbra> <compare-screenshots> <configuration> <output folder>
# Run under with-xvfb.sh. Runs `penumbra view` (validation layer / GL debug output on: any
# message makes the viewer exit non-zero) once without and once with the panel, each screenshot
# read back from the window, and checks
#  - the screenshot without the panel against `penumbra render` of the same scene, camera and
#    size: same orientation and shadows, PSNR >= 60 dB (the backends' lit parity bound);
#  - the screenshot with the panel differs from it, and only where the panel is (x < 380).
set -euo pipefail
penumbra=$1 compare=$2 configuration=$3 out=$4
size_w=640 size_h=360
rm -rf "$out"
mkdir -p "$out"
echo "display $DISPLAY"

view=("$penumbra" view --backend "$configuration" --scene test --size "${size_w}x${size_h}" --frames 4)
"${view[@]}" --no-ui --screenshot "$out/view.png"
"${view[@]}" --screenshot "$out/view-ui.png"
"$penumbra" render --backend "$configuration" --scene test --size "${size_w}x${size_h}" --out "$out/render/lit.png"

"$compare" scene "$out/render/lit.png" "$out/view.png" 60
"$compare" panel "$out/view.png" "$out/view-ui.png" 380
