// libFuzzer target: decoding of the pictures glTF images carry (PNG, JPEG) with their size limits.
#include "GltfImages.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tinygltf::Image image;
    if (penumbra::gltf::decodeImage({data, size}, image).empty() &&
        image.image.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.component) *
                                  std::size_t(image.bits / 8))
        __builtin_trap();
    return 0;
}
