#pragma once

#include "GlDebug.hpp"
#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/rhi/Configuration.hpp"

#include <memory>
#include <string>

namespace penumbra::opengl {

using GlProc = void (*)();

// One way of getting a windowless GL 4.5 core context (EGL surfaceless, OSMesa).
class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    virtual void makeCurrent() = 0;
    // Unbinds the context from the calling thread.
    virtual void release() = 0;
    virtual GlProc procAddress(const char* name) const = 0;
};

// Both throw rhi::Error naming what is missing (display, platform, version).
std::unique_ptr<HeadlessContext> createEglSurfacelessContext(bool debug);
std::unique_ptr<HeadlessContext> createOsMesaContext(bool debug);

// Fills the table through `loader`; throws rhi::Error naming the first entry point that is missing.
GlFunctions loadGlFunctions(const HeadlessContext& loader, bool polygonOffsetClamp);

// The device's context, shared by the device and every object it created, so that objects can be
// destroyed after the device: each makes the context current before deleting its GL names.
class GlContext {
public:
    GlContext(rhi::GlContextProvider provider, bool debug);
    ~GlContext();
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
    void releaseIfCurrent();

    rhi::DebugMessageLog debugLog_; // outlives context_: the debug callback points at it
    std::unique_ptr<HeadlessContext> context_;
    GlFunctions gl_;
    int version_ = 0;
};

} // namespace penumbra::opengl
