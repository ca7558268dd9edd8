#!/usr/bin/env bash
# Installs the Debian 12 packages Penumbra builds and tests with; quiet and idempotent.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers
  libegl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  glslang-dev glslang-tools spirv-cross libspirv-cross-c-shared-dev
  libglfw3-dev libglm-dev libtinygltf-dev libopenimageio-dev openimageio-tools
  libfmt-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
  libimgui-dev xvfb xauth doxygen
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run as root or install them" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
