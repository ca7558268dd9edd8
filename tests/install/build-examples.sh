#!/usr/bin/env bash
# build-examples.sh <build folder> <source folder> <work folder> <image-check> <configuration>...
# Installs the built libraries into <work folder>/prefix (cmake --install, no rebuild), configures and
# builds examples/ as an outside project against that prefix, and runs every example on each
# configuration in a folder of its own, where its picture must appear and not be flat, then the
# custom pass's parity test (every configuration in one run, penumbra::parity). The build folder's
# own package is checked too, by configuring the examples against it.
set -euo pipefail
build=$1 source=$2 work=$3 check=$4
shift 4
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# Unoptimized: the examples only call into the installed (optimized) libraries, and compile faster at -O0.
cmake -S "$source/examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG=-O0 --log-level=WARNING >/dev/null
cmake --build "$work/build" -j 1 >/dev/null
cmake -S "$source/examples" -B "$work/from-build-folder" -DCMAKE_PREFIX_PATH="$build" --log-level=WARNING >/dev/null
for configuration in "$@"; do
  mkdir -p "$work/run/$configuration"
  cd "$work/run/$configuration"
  for pair in triangle:triangle.png shadowed_scene:scene.png cascade_view:cascades.png custom_pass:custom_pass.png \
              fog_pass:fog_pass.png compute_histogram:compute_histogram.png compute_cull:compute_cull.png; do
    program=${pair%%:*} picture=${pair#*:}
    "$work/build/$program" --backend "$configuration"
    "$check" "$picture" spread 0.05 >/dev/null || { echo "$configuration: $program wrote a flat $picture"; exit 1; }
    echo "$configuration: $program -> $picture"
  done
done
mkdir -p "$work/run/parity"
cd "$work/run/parity"
"$work/build/custom_pass_parity_test"
"$work/build/fog_pass_parity_test"
