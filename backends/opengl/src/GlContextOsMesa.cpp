#include "GlContext.hpp"

#include "penumbra/rhi/Error.hpp"

#include <GL/osmesa.h>
#include <array>

namespace penumbra::opengl {
namespace {

// OSMesa wants a colour buffer to make a context current; we render into FBOs only, so 1x1 suffices.
class OsMesaContext final : public PlatformContext {
public:
    // OSMesa has no debug-context attribute; Mesa still delivers KHR_debug output once enabled.
    explicit OsMesaContext(bool /*debug*/)
    {
        const int attributes[] = {
            OSMESA_FORMAT,
            OSMESA_RGBA,
            OSMESA_DEPTH_BITS,
            0,
            OSMESA_PROFILE,
            OSMESA_CORE_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION,
            4,
            OSMESA_CONTEXT_MINOR_VERSION,
            5,
            0,
        };
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_)
            throw rhi::Error("OSMesa: cannot create an OpenGL 4.5 core context (OSMesaCreateContextAttribs failed)");
    }

    ~OsMesaContext() override { OSMesaDestroyContext(context_); }

    void makeCurrent() override
    {
        if (!OSMesaMakeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1))
            throw rhi::Error("OSMesa: OSMesaMakeCurrent failed");
    }

    void release() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

    GlProc procAddress(const char* name) const override { return OSMesaGetProcAddress(name); }

private:
    OSMesaContext context_ = nullptr;
    std::array<unsigned char, 4> pixel_{};
};

} // namespace

std::unique_ptr<PlatformContext> createOsMesaContext(bool debug) { return std::make_unique<OsMesaContext>(debug); }

} // namespace penumbra::opengl
