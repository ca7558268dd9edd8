#include "GlContext.hpp"

#include "penumbra/rhi/Error.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstring>
#include <fmt/format.h>
#include <mutex>

namespace penumbra::opengl {
namespace {

std::string eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    default:
        return fmt::format("EGL error 0x{:x}", error);
    }
}

bool hasWord(const char* list, const char* word)
{
    const std::size_t length = std::strlen(word);
    for (const char* p = list ? std::strstr(list, word) : nullptr; p; p = std::strstr(p + 1, word))
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0'))
            return true;
    return false;
}

// The surfaceless display is one per process and eglTerminate would end it for every device,
// so devices share it and the last one terminates it.
class EglDisplay {
public:
    EglDisplay()
    {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!hasWord(clientExtensions, "EGL_MESA_platform_surfaceless"))
            throw rhi::Error(fmt::format("EGL: no surfaceless platform (EGL_MESA_platform_surfaceless is missing from "
                                         "the client extensions '{}'); try the OSMesa context provider",
                                         clientExtensions ? clientExtensions : ""));
        display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY)
            throw rhi::Error(fmt::format("EGL: no surfaceless display ({})", eglErrorName(eglGetError())));
        if (!eglInitialize(display_, nullptr, nullptr))
            throw rhi::Error(
                fmt::format("EGL: cannot initialise the surfaceless display ({})", eglErrorName(eglGetError())));
    }
    ~EglDisplay() { eglTerminate(display_); }
    EglDisplay(const EglDisplay&) = delete;
    EglDisplay& operator=(const EglDisplay&) = delete;

    EGLDisplay handle() const { return display_; }

    static std::shared_ptr<EglDisplay> shared()
    {
        static std::mutex mutex;
        static std::weak_ptr<EglDisplay> instance;
        std::lock_guard lock(mutex);
        std::shared_ptr<EglDisplay> display = instance.lock();
        if (!display) {
            display = std::make_shared<EglDisplay>();
            instance = display;
        }
        return display;
    }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
};

class EglSurfacelessContext final : public PlatformContext {
public:
    explicit EglSurfacelessContext(bool debug) : display_(EglDisplay::shared())
    {
        const EGLDisplay dpy = display_->handle();
        const char* extensions = eglQueryString(dpy, EGL_EXTENSIONS);
        if (!hasWord(extensions, "EGL_KHR_surfaceless_context"))
            throw rhi::Error("EGL: the display lacks EGL_KHR_surfaceless_context");
        if (!eglBindAPI(EGL_OPENGL_API))
            throw rhi::Error(fmt::format("EGL: no desktop OpenGL API ({})", eglErrorName(eglGetError())));

        EGLConfig config = EGL_NO_CONFIG_KHR;
        if (!hasWord(extensions, "EGL_KHR_no_config_context")) {
            const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            EGLint found = 0;
            if (!eglChooseConfig(dpy, configAttributes, &config, 1, &found) || found == 0)
                throw rhi::Error("EGL: the surfaceless display has no desktop OpenGL config");
        }
        // Lose the context on a GPU reset, so that glGetGraphicsResetStatus reports it (GlDevice::apiSubmit), where
        // the display offers robust contexts (EGL_EXT_create_context_robustness; for desktop OpenGL the attribute is
        // EGL 1.5's, EGL specification section 3.7.1.5); the last two entries end the list otherwise.
        const bool resets = hasWord(extensions, "EGL_EXT_create_context_robustness");
        const EGLint contextAttributes[] = {
            EGL_CONTEXT_MAJOR_VERSION,
            4,
            EGL_CONTEXT_MINOR_VERSION,
            5,
            EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_CONTEXT_OPENGL_DEBUG,
            debug ? EGL_TRUE : EGL_FALSE,
            resets ? EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY : EGL_NONE,
            EGL_LOSE_CONTEXT_ON_RESET,
            EGL_NONE,
        };
        context_ = eglCreateContext(dpy, config, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT)
            throw rhi::Error(fmt::format("EGL: cannot create an OpenGL 4.5 core{} context ({}); the driver may "
                                         "not offer GL 4.5 core",
                                         debug ? " debug" : "", eglErrorName(eglGetError())));
    }

    ~EglSurfacelessContext() override { eglDestroyContext(display_->handle(), context_); }

    void makeCurrent() override
    {
        if (!eglMakeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw rhi::Error(fmt::format("EGL: eglMakeCurrent failed ({})", eglErrorName(eglGetError())));
    }

    void release() override { eglMakeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

    GlProc procAddress(const char* name) const override { return eglGetProcAddress(name); }

private:
    std::shared_ptr<EglDisplay> display_;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace

std::unique_ptr<PlatformContext> createEglSurfacelessContext(bool debug)
{
    return std::make_unique<EglSurfacelessContext>(debug);
}

} // namespace penumbra::opengl
