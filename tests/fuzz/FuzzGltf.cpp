// libFuzzer target: the glTF loader on a .gltf (JSON with data-URI or external buffers and images) or a
// .glb, told apart by content; external files are looked up in PENUMBRA_FUZZ_RESOURCES.
#include "penumbra/gltf/GltfLoader.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try {
        penumbra::gltf::loadGltf({data, size}, "fuzz.gltf", PENUMBRA_FUZZ_RESOURCES);
    } catch (const penumbra::gltf::GltfError&) {
    }
    return 0;
}
