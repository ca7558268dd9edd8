#pragma once

#include "penumbra/rhi/Image.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::imageio {

// PNG (stb_image_write, stb_image) and OpenEXR (the OpenEXR library) files of pictures and depth, kept out of the RHI
// so that it links no codec. Encoding goes to memory; the write* functions then write the file whole with
// rhi::writeFileAtomically, so no reader sees half a file. Failures throw rhi::Error naming the path.

// 32-bit float channels, interleaved, row 0 at the top (OpenEXR's increasing-Y scanline order).
struct FloatImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::string> channels; // names, e.g. {"R", "G", "B", "A"} or {"Z"}
    std::vector<float> values; // width * height * channels.size()

    // The index of the channel called `name` ("R", "Z", ...), or nullopt.
    std::optional<std::size_t> channelIndex(std::string_view name) const;
    // The value of one channel of texel (x, y), row 0 at the top.
    float at(std::uint32_t x, std::uint32_t y, std::size_t channel) const
    {
        return values[(std::size_t(y) * width + x) * channels.size() + channel];
    }
};

// An RGBA8 picture as PNG bytes (zlib level 8 of stb_image_write, the same bytes on every run); other formats throw.
std::string encodePng(const rhi::Image& image);
// Any 8- or 16-bit PNG as RGBA8: grey replicated to RGB, alpha 255 where the file has none (stb_image's conversion).
rhi::Image readPng(const std::filesystem::path& path);
// encodePng written to `path`; throws "cannot write <path>: <reason>".
void writePngFile(const std::filesystem::path& path, const rhi::Image& image);

// One-part scanline OpenEXR with ZIP compression, every channel 32-bit float, in `image.channels`' names.
std::string encodeExr(const FloatImage& image);
// Every channel of a one-part scanline EXR, in the file's order (OpenEXR sorts names); channels other than 32-bit
// float are refused, since only Penumbra's own depth and picture files are read.
FloatImage readExr(const std::filesystem::path& path);
// A Radiance RGBE (.hdr) picture as linear R, G, B floats (stb_image's decoder).
FloatImage readHdr(const std::filesystem::path& path);
// The R, G and B channels of a one-part scanline EXR of any pixel type (half too, as most HDR photographs are),
// converted to float by OpenEXR; a file without them is refused, naming it.
FloatImage readExrColor(const std::filesystem::path& path);
// encodeExr written to `path`; throws "cannot write <path>: <reason>".
void writeExrFile(const std::filesystem::path& path, const FloatImage& image);

} // namespace penumbra::imageio
