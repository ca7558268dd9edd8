#pragma once

#include "penumbra/rhi/Image.hpp"

#include <filesystem>
#include <string_view>

namespace penumbra::parity {

// Writes through imageio/ImageFiles.hpp, hence rhi::writeFileAtomically (parent folders created, a
// temporary file renamed into place); a failure throws rhi::Error "cannot write <path>: <reason>".
void writePng(const std::filesystem::path& path, const rhi::Image& image);
// The raw depth values as one 32-bit float channel, exactly as read back.
void writeExr(const std::filesystem::path& path, const rhi::DepthImage& depth);
// A rendered RGBA8 picture (sRGB-encoded) by the path's extension: .png as it is, .exr as linear
// 32-bit float RGBA (the sRGB curve undone, as EXR readers expect). Other extensions throw.
void writePicture(const std::filesystem::path& path, const rhi::Image& image);
// Whether writePicture takes this path's extension.
bool isPicturePath(const std::filesystem::path& path);
// A report or other text file, written by rhi::writeFileAtomically like the pictures.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

} // namespace penumbra::parity
