#pragma once

#include "GlDebug.hpp"
#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/opengl/OpenGLDevice.hpp"
#include "penumbra/rhi/Configuration.hpp"

#include <memory>
#include <string>

namespace penumbra::opengl {

using GlProc = void (*)();

// One way of getting a GL 4.5 core context: windowless (EGL surfaceless, OSMesa) or a GLFW window's.
class PlatformContext {
public:
    virtual ~PlatformContext() = default;
    virtual void makeCurrent() = 0;
    // Unbinds the context from the calling thread.
    virtual void release() = 0;
    virtual GlProc procAddress(const char* name) const = 0;
};

// Both throw rhi::Error naming what is missing (display, platform, version).
std::unique_ptr<PlatformContext> createEglSurfacelessContext(bool debug);
std::unique_ptr<PlatformContext> createOsMesaContext(bool debug);
// The context GLFW made with the window (penumbra::prepareWindowHints asked for 4.5 core).
std::unique_ptr<PlatformContext> createGlfwWindowContext(GLFWwindow* window);

// Fills the table through `loader`; throws rhi::Error naming the first entry point that is missing. The optional
// entry points are looked up where the version or extensions say the driver has them.
GlFunctions loadGlFunctions(const PlatformContext& loader, bool polygonOffsetClamp, bool indirectCount);

// The device's context, shared by the device and every object it created, so that objects can be
// destroyed after the device: each makes the context current before deleting its GL names.
class GlContext {
public:
    // The window's context when desc.window has one, else options.context's headless one.
    GlContext(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options);
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Cheap when already current on this thread (cached per thread).
    void makeCurrent() const;
    const GlFunctions& gl() const { return gl_; }
    rhi::DebugMessageLog& debugLog() { return debugLog_; }
    const rhi::DebugMessageLog& debugLog() const { return debugLog_; }
    bool hasExtension(const std::string& name) const;
    int version() const { return version_; } // major * 10 + minor

private:
    void initialize();
    // Unbinds the context from the calling thread if it is current there.
    void releaseIfCurrent() const;

    rhi::DebugMessageLog debugLog_; // outlives context_: the debug callback points at it
    std::unique_ptr<PlatformContext> context_;
    GlFunctions gl_;
    int version_ = 0;
    // Declared last, so destroyed first, and also when the constructor throws after making the
    // context current: nothing may stay current on a destroyed context.
    struct Release {
        const GlContext& owner;
        ~Release() { owner.releaseIfCurrent(); }
    } release_{*this};
};

} // namespace penumbra::opengl
