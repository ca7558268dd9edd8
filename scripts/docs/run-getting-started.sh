#!/usr/bin/env bash
# docs.getting-started: run-getting-started.sh <build folder> <source folder> <work folder> <image-check>
# Runs docs/getting-started.md's steps as written: the files its blocks name (```cmake file=..., ```cpp example
# file=...) are written into a scratch folder standing for the repository root, where `build` and `tests` link to
# the real ones; then its ```sh getting-started blocks run there, in order. The pictures they write must not be flat.
set -euo pipefail
build=$1 source=$2 work=$3 check=$4
rm -rf "$work"
mkdir -p "$work"
ln -s "$(cd "$build" && pwd)" "$work/build"
ln -s "$(cd "$source" && pwd)/tests" "$work/tests"
python3 "$source/scripts/docs/extract.py" steps "$source" "$work"
cd "$work"
bash -euo pipefail getting-started.sh
for picture in first-vulkan.png first-opengl.png; do
  "$check" "$picture" spread 0.05 >/dev/null || { echo "getting-started: $picture is missing or flat"; exit 1; }
  echo "getting-started: $picture"
done
