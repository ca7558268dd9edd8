#include "FrameChecks.hpp"

#include "penumbra/rhi/Error.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::render {

void checkFrameSize(const FrameDesc& frame)
{
    if (frame.width == 0 || frame.height == 0)
        throw rhi::Error(
            fmt::format("frame size {}x{}: width and height must be at least 1", frame.width, frame.height));
}

void checkPlansFitFrame(const ShadowPlans& plans, const shadows::ShadowSettings& settings)
{
    if (plans.directional.atlas.atlasSize() != settings.directional.atlasSize)
        throw rhi::Error(fmt::format("shadow plans: the directional plan is for a {}-texel atlas, the frame's "
                                     "directional.atlasSize is {}",
                                     plans.directional.atlas.atlasSize(), settings.directional.atlasSize));
    if (plans.local.atlasSize != settings.local.atlasSize)
        throw rhi::Error(fmt::format("shadow plans: the spot and point plan is for a {}-texel atlas, the frame's "
                                     "local.atlasSize is {}",
                                     plans.local.atlasSize, settings.local.atlasSize));
    if (!plans.local.cubes.empty() && settings.local.pointMode != shadows::PointShadowMode::CubeMap)
        throw rhi::Error("shadow plans: the spot and point plan has shadow cube maps, the frame's local.pointMode "
                         "is atlas");
    if (plans.local.cubes.size() > shadows::maxShadowCubes)
        throw rhi::Error(fmt::format("shadow plans: {} shadow cube maps, at most {}", plans.local.cubes.size(),
                                     shadows::maxShadowCubes));
}

void checkMsaa(const FrameDesc& frame, const rhi::Capabilities& caps)
{
    if (frame.msaa != 1 && frame.msaa != 2 && frame.msaa != 4 && frame.msaa != 8)
        throw rhi::Error(fmt::format("FrameDesc::msaa: {} is not 1, 2, 4 or 8", frame.msaa));
    const std::array targets{kLitColorFormat, kLitDepthFormat};
    const std::uint32_t offered = caps.sampleCounts(targets);
    if ((offered & frame.msaa) == 0)
        throw rhi::UnsupportedError(fmt::format("msaa {}: {} offers {} samples per pixel for the lit pass ({} colour, "
                                                "{} depth)",
                                                frame.msaa, caps.device, rhi::sampleCountList(offered),
                                                rhi::formatName(kLitColorFormat), rhi::formatName(kLitDepthFormat)));
}

void checkShadowPath(const FrameDesc& frame)
{
    if (frame.shadowPath == ShadowPath::ScreenSpace && !frame.depthPrepass)
        throw rhi::Error("FrameDesc::shadowPath: the screen-space shadow path collects shadows from the depth "
                         "prepass's depth; it needs FrameDesc::depthPrepass");
    if (frame.shadows.contact.shadows == shadows::Toggle::On && !frame.depthPrepass)
        throw rhi::Error("contact.shadows: contact shadows march through the depth prepass's depth; they need "
                         "FrameDesc::depthPrepass");
}

} // namespace penumbra::render
