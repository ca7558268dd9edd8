#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/TextureImage.hpp"

namespace penumbra::gltf {

// glTF sampler `index` (-1: none, glTF's repeat and auto filtering) as a TextureSampler; a filter or wrap code
// the specification does not list fails naming the sampler, the field and the value.
scene::TextureSampler textureSampler(const Document& document, int index, const std::string& owner);

} // namespace penumbra::gltf
