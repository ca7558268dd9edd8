#pragma once

#include "GltfFields.hpp"

#include <tiny_gltf.h>

namespace penumbra::gltf {

// Checks the byte ranges of a file whose JSON passed checkSchema, now that its buffers are read: each
// buffer holds the bytes it declares, each buffer view lies inside its buffer, each accessor's
// elements inside its buffer view, at offsets aligned to its component size, with a byteStride no
// smaller than an element; accessor counts stay within kMaxAccessorElements. Throws GltfError naming
// the JSON pointer of the offending value.
void checkLayout(const JsonFile& file, const tinygltf::Model& model);

} // namespace penumbra::gltf
