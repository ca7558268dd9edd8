#pragma once

#include "penumbra/rhi/Image.hpp"

#include <filesystem>

namespace penumbra::apps {

// Writes through OpenImageIO, creating parent folders; a failure throws rhi::Error naming the
// file. Files are written to a temporary name and renamed, so nothing is left half-written.
void writePng(const std::filesystem::path& path, const rhi::Image& image);
// The raw depth values as one 32-bit float channel, exactly as read back.
void writeExr(const std::filesystem::path& path, const rhi::DepthImage& depth);

} // namespace penumbra::apps
