#include "penumbra/parity/ImageFiles.hpp"

#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <vector>

namespace penumbra::parity {

void writePng(const std::filesystem::path& path, const rhi::Image& image) { imageio::writePngFile(path, image); }

void writeExr(const std::filesystem::path& path, const rhi::DepthImage& depth)
{
    imageio::writeExrFile(path, {depth.width, depth.height, {"Z"}, depth.depth});
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
    imageio::FloatImage linear{image.width, image.height, {"R", "G", "B", "A"}, std::vector<float>(image.bytes.size())};
    for (std::size_t i = 0; i < image.bytes.size(); ++i) {
        const double stored = double(image.bytes[i]) / 255.0;
        linear.values[i] = float(i % 4 == 3 ? stored : rhi::srgbToLinear(stored));
    }
    imageio::writeExrFile(path, linear);
}

void writeTextFile(const std::filesystem::path& path, std::string_view text) { rhi::writeFileAtomically(path, text); }

} // namespace penumbra::parity
