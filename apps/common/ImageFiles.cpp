#include "ImageFiles.hpp"

#include "penumbra/rhi/Error.hpp"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

void writeImage(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const void* pixels)
{
    std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
    const std::filesystem::path temporary = path.string() + ".partial" + path.extension().string();
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw rhi::Error(fmt::format("{}: no image writer: {}", path.string(), OIIO::geterror()));
    if (!out->open(temporary.string(), spec) || !out->write_image(spec.format, pixels) || !out->close()) {
        const std::string why = out->geterror();
        std::filesystem::remove(temporary);
        throw rhi::Error(fmt::format("{}: cannot write: {}", path.string(), why));
    }
    std::filesystem::rename(temporary, path);
}

} // namespace

void writePng(const std::filesystem::path& path, const rhi::Image& image)
{
    if (image.format != rhi::Format::RGBA8)
        throw rhi::Error(fmt::format("{}: PNG needs RGBA8, the image is {}", path.string(), rhi::formatName(image.format)));
    writeImage(path, OIIO::ImageSpec(int(image.width), int(image.height), 4, OIIO::TypeDesc::UINT8), image.bytes.data());
}

void writeExr(const std::filesystem::path& path, const rhi::DepthImage& depth)
{
    OIIO::ImageSpec spec(int(depth.width), int(depth.height), 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Z"};
    writeImage(path, spec, depth.depth.data());
}

} // namespace penumbra::apps
