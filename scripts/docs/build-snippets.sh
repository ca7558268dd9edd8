#!/usr/bin/env bash
# docs.snippets: build-snippets.sh <build folder> <source folder> <work folder>
# Every C++ block of README.md and docs/ marked as an example (```cpp example) is compiled, in one project and one
# build, against the package installed from the build folder (cmake --install, as install.examples does). Blocks
# that name a file (```cpp example file=...) belong to a page's steps, which docs.getting-started builds and runs.
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/snippets"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
python3 "$source/scripts/docs/extract.py" snippets "$source" "$work/snippets"
cmake -S "$work/snippets" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
      --log-level=WARNING >/dev/null
cmake --build "$work/build" -j 2
