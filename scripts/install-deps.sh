#!/usr/bin/env bash
# Installs the Debian 12 packages Penumbra builds and tests with; quiet and idempotent.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers
  libegl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  glslang-dev glslang-tools spirv-cross libspirv-cross-c-shared-dev
  libglfw3-dev libglm-dev libtinygltf-dev libopenexr-dev
  libstb-dev libfmt-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libpng-dev
  libimgui-dev xvfb xauth doxygen clang-format clang-tidy python3
)

# The Khronos glTF Validator, the loader tests' oracle (tests/scene/GltfValidatorTest.cpp), from npm.
install_gltf_validator() {
  command -v node >/dev/null && [ -d "$(npm root -g 2>/dev/null)/gltf-validator" ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: missing the npm package gltf-validator; run as root or npm install -g gltf-validator" >&2
    exit 1
  fi
  command -v npm >/dev/null || { apt-get update -qq && apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null; }
  echo "install-deps: installing gltf-validator (npm)"
  npm install -g --silent gltf-validator >/dev/null
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  install_gltf_validator
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run as root or install them" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_gltf_validator
