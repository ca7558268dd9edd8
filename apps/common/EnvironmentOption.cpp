#include "EnvironmentOption.hpp"

#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/rhi/Error.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <mutex>

namespace penumbra::apps {
namespace {

std::shared_ptr<const render::EnvironmentImage> readEnvironmentFile(const std::string& path, const std::string& what)
{
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".hdr" && extension != ".exr")
        throw rhi::Error(fmt::format("{} '{}': not a .hdr or .exr file, nor default, none or auto", what, path));
    if (!std::filesystem::exists(path))
        throw rhi::Error(fmt::format("{} '{}': no such file", what, path));
    const imageio::FloatImage file = extension == ".hdr" ? imageio::readHdr(path) : imageio::readExrColor(path);
    auto image = std::make_shared<render::EnvironmentImage>();
    image->width = file.width;
    image->height = file.height;
    image->texels.reserve(std::size_t(file.width) * file.height);
    for (std::size_t i = 0; i + 2 < file.values.size(); i += 3)
        image->texels.emplace_back(file.values[i], file.values[i + 1], file.values[i + 2]);
    render::validate(*image, path);
    return image;
}

// One image per path and one studio image per process: the renderer prefilters an image once, by pointer.
std::shared_ptr<const render::EnvironmentImage> cachedImage(const std::string& source, const std::string& what)
{
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const render::EnvironmentImage>> images;
    const std::lock_guard lock(mutex);
    auto& image = images[source];
    if (!image)
        image = source == "default" ? std::make_shared<const render::EnvironmentImage>(render::studioEnvironment())
                                    : readEnvironmentFile(source, what);
    return image;
}

} // namespace

render::EnvironmentLight environmentOf(const std::string& source, bool autoStudio, float intensity,
                                       float rotationDegrees, const std::string& what)
{
    render::EnvironmentLight environment{nullptr, intensity, rotationDegrees};
    render::validate(environment);
    if (source == "none" || (source == "auto" && !autoStudio))
        return environment;
    environment.image = cachedImage(source == "auto" ? "default" : source, what);
    return environment;
}

} // namespace penumbra::apps
