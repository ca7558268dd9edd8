#include "penumbra/shaders/ShaderLibrary.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <utility>

namespace penumbra::shaders {
namespace detail {
extern const std::pair<std::string_view, std::string_view> embedded[];
extern const std::size_t embeddedCount;
} // namespace detail

std::string_view source(std::string_view fileName)
{
    std::string known;
    for (std::size_t i = 0; i < detail::embeddedCount; ++i) {
        if (detail::embedded[i].first == fileName)
            return detail::embedded[i].second;
        known += fmt::format("{}{}", known.empty() ? "" : ", ", detail::embedded[i].first);
    }
    throw rhi::Error(fmt::format("no shader named '{}'; known shaders: {}", fileName, known));
}

rhi::ShaderSource load(std::string_view fileName)
{
    const bool vertex = fileName.ends_with(".vert");
    if (!vertex && !fileName.ends_with(".frag"))
        throw rhi::Error(fmt::format("shader '{}': the extension must be .vert or .frag", fileName));
    rhi::ShaderSource shader{vertex ? rhi::ShaderStage::Vertex : rhi::ShaderStage::Fragment,
                             std::string(source(fileName)), std::string(fileName), {}};
    for (std::size_t i = 0; i < detail::embeddedCount; ++i)
        if (detail::embedded[i].first.ends_with(".glsl"))
            shader.includes.push_back({std::string(detail::embedded[i].first), std::string(detail::embedded[i].second)});
    return shader;
}

} // namespace penumbra::shaders
