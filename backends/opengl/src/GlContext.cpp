#include "GlContext.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::opengl {
namespace {

// The context we last made current on this thread; skips redundant MakeCurrent calls.
thread_local const GlContext* currentContext = nullptr;
thread_local PlatformContext* currentPlatform = nullptr;

std::unique_ptr<PlatformContext> createPlatformContext(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options)
{
    if (desc.window.glfwWindow)
        return createGlfwWindowContext(desc.window.glfwWindow);
    return options.context == ContextProvider::OSMesa ? createOsMesaContext(desc.validation)
                                                      : createEglSurfacelessContext(desc.validation);
}

} // namespace

GlContext::GlContext(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options)
    : context_(createPlatformContext(desc, options))
{
    initialize();
}

void GlContext::initialize()
{
    // Current first: GLFW looks entry points up only for the current context.
    makeCurrent();
    // Which optional entry points exist depends on the version and extensions: query those first.
    auto getIntegerv = reinterpret_cast<PFNGLGETINTEGERVPROC>(context_->procAddress("glGetIntegerv"));
    auto getStringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(context_->procAddress("glGetStringi"));
    if (!getIntegerv || !getStringi)
        throw rhi::Error("OpenGL: the driver does not provide glGetIntegerv / glGetStringi");
    GLint major = 0;
    GLint minor = 0;
    getIntegerv(GL_MAJOR_VERSION, &major);
    getIntegerv(GL_MINOR_VERSION, &minor);
    version_ = major * 10 + minor;
    if (version_ < 45)
        throw rhi::Error(fmt::format("OpenGL: a 4.5 core context is required, the driver gave {}.{}", major, minor));
    gl_.GetIntegerv = getIntegerv;
    gl_.GetStringi = getStringi;
    const bool clamp =
        version_ >= 46 || hasExtension("GL_ARB_polygon_offset_clamp") || hasExtension("GL_EXT_polygon_offset_clamp");
    const bool indirectCount = version_ >= 46 || hasExtension("GL_ARB_indirect_parameters");
    gl_ = loadGlFunctions(*context_, clamp, indirectCount);
}

void GlContext::releaseIfCurrent() const
{
    if (currentContext != this)
        return;
    context_->release();
    currentContext = nullptr;
    currentPlatform = nullptr;
}

void GlContext::makeCurrent() const
{
    if (currentContext == this)
        return;
    // EGL and OSMesa each track their own current context; unbind the other one so neither is stale.
    if (currentPlatform)
        currentPlatform->release();
    currentContext = nullptr;
    currentPlatform = nullptr;
    context_->makeCurrent();
    currentContext = this;
    currentPlatform = context_.get();
}

bool GlContext::hasExtension(const std::string& name) const
{
    makeCurrent();
    GLint count = 0;
    gl_.GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (name == reinterpret_cast<const char*>(gl_.GetStringi(GL_EXTENSIONS, GLuint(i))))
            return true;
    return false;
}

} // namespace penumbra::opengl
