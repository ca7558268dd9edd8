#include "penumbra/parity/ImageFiles.hpp"

#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <vector>

namespace penumbra::parity {
namespace {

// Encoded in memory by the writer the path's extension names, then written as one file by
// rhi::writeFileAtomically, so every picture shares the text files' temporary-and-rename path.
void writeImage(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const void* pixels)
{
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw rhi::Error(fmt::format("cannot write {}: no image writer: {}", path.string(), OIIO::geterror()));
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!out->set_ioproxy(&memory) || !out->open(path.string(), spec) || !out->write_image(spec.format, pixels) ||
        !out->close())
        throw rhi::Error(fmt::format("cannot write {}: {}", path.string(), out->geterror()));
    rhi::writeFileAtomically(path, {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
}

} // namespace

void writePng(const std::filesystem::path& path, const rhi::Image& image)
{
    if (image.format != rhi::Format::RGBA8)
        throw rhi::Error(
            fmt::format("{}: PNG needs RGBA8, the image is {}", path.string(), rhi::formatName(image.format)));
    writeImage(path, OIIO::ImageSpec(int(image.width), int(image.height), 4, OIIO::TypeDesc::UINT8),
               image.bytes.data());
}

void writeExr(const std::filesystem::path& path, const rhi::DepthImage& depth)
{
    OIIO::ImageSpec spec(int(depth.width), int(depth.height), 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Z"};
    writeImage(path, spec, depth.depth.data());
}

bool isPicturePath(const std::filesystem::path& path)
{
    return path.extension() == ".png" || path.extension() == ".exr";
}

void writePicture(const std::filesystem::path& path, const rhi::Image& image)
{
    if (path.extension() == ".png")
        return writePng(path, image);
    if (path.extension() != ".exr")
        throw rhi::Error(fmt::format("{}: pictures are written as .png or .exr", path.string()));
    if (image.format != rhi::Format::RGBA8)
        throw rhi::Error(
            fmt::format("{}: needs an RGBA8 picture, the image is {}", path.string(), rhi::formatName(image.format)));
    std::vector<float> linear(image.bytes.size());
    for (std::size_t i = 0; i < image.bytes.size(); ++i) {
        const double stored = double(image.bytes[i]) / 255.0;
        linear[i] = float(i % 4 == 3 ? stored : rhi::srgbToLinear(stored));
    }
    writeImage(path, OIIO::ImageSpec(int(image.width), int(image.height), 4, OIIO::TypeDesc::FLOAT), linear.data());
}

void writeTextFile(const std::filesystem::path& path, std::string_view text) { rhi::writeFileAtomically(path, text); }

} // namespace penumbra::parity
