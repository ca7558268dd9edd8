#pragma once

#include "GltfDocument.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::gltf {

// Reads a .gltf (JSON) or .glb (binary container, glTF 2.0 section 4.4) file, told apart by content,
// and checks it as the Khronos glTF Validator does (checkSchema, then the byte ranges of buffers,
// buffer views and accessors once the buffers are read) within the limits of GltfLimits.hpp. Throws
// GltfError "<path>: <JSON pointer>: <what>"; tinygltf's warnings become notes.
// An image file that cannot be read is left empty and listed (Document::missingImage), for the material that uses it
// to refuse or stand in for as `missingTextures` says. Images are decoded in parallel (decodeStashedImages), with
// progress(done, total) after each.
Document readDocument(const std::filesystem::path& path, std::vector<std::string>& notes,
                      MissingTextures missingTextures = MissingTextures::Fail,
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

// The same for a file's bytes, with external buffers and images looked up in `folder`.
Document readDocument(const std::string& name, std::span<const std::uint8_t> bytes, const std::filesystem::path& folder,
                      std::vector<std::string>& notes, MissingTextures missingTextures = MissingTextures::Fail,
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

} // namespace penumbra::gltf
