#include "GlOrientation.hpp"

#include "GlContext.hpp"
#include "penumbra/rhi/Error.hpp"

namespace penumbra::opengl {

rhi::Conventions GlOrientation::conventions(bool reversedZ) const
{
    return rhi::Conventions(clipControl_ ? rhi::DepthRange::ZeroToOne : rhi::DepthRange::MinusOneToOne, reversedZ);
}

void GlOrientation::apply(const GlContext& context) const
{
    context.gl().ProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    if (!clipControl_)
        return;
    if (context.version() < 45 && !context.hasExtension("GL_ARB_clip_control"))
        throw rhi::UnsupportedError("OpenGL: glClipControl is unavailable (needs GL 4.5 or GL_ARB_clip_control); "
                                    "use the opengl-noclip configuration (DeviceDesc::depthRange = MinusOneToOne)");
    context.gl().ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
}

} // namespace penumbra::opengl
