#pragma once

#include "GltfDocument.hpp"

#include <string>
#include <vector>

namespace penumbra::gltf {

// Fails for an extension in extensionsRequired that the loader does not implement; adds one note per
// file for each extension outside the supported list it leaves out, so nothing is dropped silently.
void checkSupport(const Document& document, std::vector<std::string>& notes);

} // namespace penumbra::gltf
