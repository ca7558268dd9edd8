#include "penumbra/parity/ImageFiles.hpp"

#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"

#include <OpenImageIO/imageio.h>
#include <fstream>
#include <fmt/format.h>
#include <unistd.h>
#include <vector>

namespace penumbra::parity {
namespace {

// Written first and renamed into place, so no reader sees half a file; named per process, so that two
// processes writing the same file (tests running in parallel, two runs of the tool) never share one.
std::filesystem::path temporaryFor(const std::filesystem::path& path)
{
    return fmt::format("{}.partial-{}{}", path.string(), ::getpid(), path.extension().string());
}

void writeImage(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const void* pixels)
{
    std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
    const std::filesystem::path temporary = temporaryFor(path);
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
        throw rhi::Error(fmt::format("{}: needs an RGBA8 picture, the image is {}", path.string(),
                                     rhi::formatName(image.format)));
    std::vector<float> linear(image.bytes.size());
    for (std::size_t i = 0; i < image.bytes.size(); ++i) {
        const double stored = double(image.bytes[i]) / 255.0;
        linear[i] = float(i % 4 == 3 ? stored : rhi::srgbToLinear(stored));
    }
    writeImage(path, OIIO::ImageSpec(int(image.width), int(image.height), 4, OIIO::TypeDesc::FLOAT), linear.data());
}

void writeTextFile(const std::filesystem::path& path, std::string_view text)
{
    std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
    const std::filesystem::path temporary = temporaryFor(path);
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) {
            std::filesystem::remove(temporary);
            throw rhi::Error(fmt::format("{}: cannot write", path.string()));
        }
    }
    std::filesystem::rename(temporary, path);
}

} // namespace penumbra::parity
