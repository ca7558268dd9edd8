#include "penumbra/parity/Picture.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::parity {

Picture colorPicture(std::string name, rhi::Image image)
{
    return {.name = std::move(name), .kind = PictureKind::Color, .color = std::move(image)};
}

Picture depthPicture(std::string name, rhi::DepthImage depth)
{
    return {.name = std::move(name),
            .kind = PictureKind::Depth,
            .depth = std::move(depth),
            .space = DepthSpace::FromFarPlane};
}

Picture viewDepthPicture(std::string name, rhi::DepthImage depth, const glm::mat4& projection)
{
    return {.name = std::move(name),
            .kind = PictureKind::Depth,
            .depth = std::move(depth),
            .space = DepthSpace::LinearView,
            .projection = projection};
}

Picture depthPicture(std::string name, rhi::DepthImage depth, std::vector<float> comparable)
{
    return {.name = std::move(name),
            .kind = PictureKind::Depth,
            .depth = std::move(depth),
            .space = DepthSpace::Given,
            .given = std::move(comparable)};
}

Picture floatPicture(std::string name, std::uint32_t width, std::uint32_t height, std::vector<float> values)
{
    return {.name = std::move(name), .kind = PictureKind::Float, .depth = {width, height, std::move(values)}};
}

const char* kindName(PictureKind kind)
{
    switch (kind) {
    case PictureKind::Color:
        return "colour";
    case PictureKind::Depth:
        return "depth";
    case PictureKind::Float:
        return "float";
    }
    return "?";
}

namespace {

const char* spaceName(DepthSpace space)
{
    switch (space) {
    case DepthSpace::FromFarPlane:
        return "window depth from the far plane";
    case DepthSpace::LinearView:
        return "linear view depth";
    case DepthSpace::Given:
        return "the render function's own values";
    }
    return "?";
}

bool isFileStem(const std::string& name)
{
    return !name.empty() && name != "." && name != ".." && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
               c == '.';
    });
}

} // namespace

std::string describe(const Picture& picture)
{
    switch (picture.kind) {
    case PictureKind::Color:
        return fmt::format("{} {}x{}", rhi::formatName(picture.color.format), picture.color.width,
                           picture.color.height);
    case PictureKind::Depth:
        return fmt::format("depth {}x{} ({})", picture.depth.width, picture.depth.height, spaceName(picture.space));
    case PictureKind::Float:
        return fmt::format("float {}x{}", picture.depth.width, picture.depth.height);
    }
    return "?";
}

void validate(const Picture& picture)
{
    if (!isFileStem(picture.name))
        throw rhi::Error(fmt::format("picture name '{}': use letters, digits, '-', '_' and '.' (it names the report's "
                                     "files)",
                                     picture.name));
    const std::size_t texels = std::size_t(picture.width()) * picture.height();
    if (texels == 0)
        throw rhi::Error(fmt::format("picture '{}': empty ({})", picture.name, describe(picture)));
    if (picture.kind == PictureKind::Color) {
        if (rhi::isDepthFormat(picture.color.format))
            throw rhi::Error(fmt::format("picture '{}': a colour picture of depth format {}; read depth with "
                                         "rhi::readDepth and pass it as a depth picture",
                                         picture.name, rhi::formatName(picture.color.format)));
        if (picture.color.bytes.size() != texels * rhi::texelSize(picture.color.format))
            throw rhi::Error(fmt::format("picture '{}': {} bytes for {} ({} expected)", picture.name,
                                         picture.color.bytes.size(), describe(picture),
                                         texels * rhi::texelSize(picture.color.format)));
        return;
    }
    if (picture.depth.depth.size() != texels)
        throw rhi::Error(
            fmt::format("picture '{}': {} values for {}", picture.name, picture.depth.depth.size(), describe(picture)));
    if (picture.kind == PictureKind::Depth && picture.space == DepthSpace::Given && picture.given.size() != texels)
        throw rhi::Error(fmt::format("picture '{}': {} comparable values for {}", picture.name, picture.given.size(),
                                     describe(picture)));
}

ComparableValues comparableValues(const Picture& picture, const rhi::Conventions& conventions)
{
    const std::vector<float>& raw = picture.depth.depth;
    ComparableValues out{std::vector<float>(raw.size()), std::vector<bool>(raw.size(), true)};
    if (picture.kind == PictureKind::Float) {
        out.values = raw;
        return out;
    }
    const float near = conventions.nearDepth();
    const float far = conventions.farDepth();
    for (std::size_t i = 0; i < raw.size(); ++i) {
        switch (picture.space) {
        case DepthSpace::FromFarPlane:
            out.values[i] = (raw[i] - far) / (near - far);
            out.drawn[i] = raw[i] != far;
            break;
        case DepthSpace::LinearView:
            out.drawn[i] = raw[i] != far;
            out.values[i] = out.drawn[i] ? conventions.viewDepth(picture.projection, raw[i]) : 0.0f;
            break;
        case DepthSpace::Given:
            out.values[i] = picture.given[i];
            out.drawn[i] = picture.given[i] > 0.0f;
            break;
        }
    }
    return out;
}

} // namespace penumbra::parity
