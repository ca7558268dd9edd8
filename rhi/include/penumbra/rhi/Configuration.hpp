#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Window.hpp"

#include <memory>
#include <string>

namespace penumbra::rhi {

class PipelineCache;

// What a device is created with: the same fields for every backend. Options that only one API
// has (the OpenGL context provider, for example) are arguments of that backend's own factory
// (penumbra/opengl/OpenGLDevice.hpp), not fields here.
struct DeviceDesc {
    // The registered name of the backend that creates the device ("vulkan", "opengl"); the
    // backends module lists them (penumbra::registeredBackends()).
    std::string backend = "vulkan";
    // Clip-space depth range. MinusOneToOne is OpenGL's range without glClipControl; a backend
    // that cannot give the range asked for throws UnsupportedError.
    DepthRange depthRange = DepthRange::ZeroToOne;
    bool reversedZ = false;
    // Vulkan validation layer / GL debug output. Every message is recorded (see
    // Device::debugMessages) and, with throwOnDebugMessage, raised as an Error at the next submit.
    bool validation = true;
    bool throwOnDebugMessage = false;
    // The RHI's own validation layer (rhi/src/validation): every rule these headers state is checked at the
    // call that breaks it, with the same Error or UnsupportedError and the same text on every backend (the
    // rules: tests/gpu/MisuseTest.cpp). On by default, as in every test; the tools turn it off in release
    // builds unless given --validate. Without it a broken rule is undefined behaviour, as in the APIs.
    bool validateUsage = true;
    // Draw counts read on the GPU where the device has them (Capabilities::drawIndirectCount); false takes the
    // RHI's emulation everywhere, so tests can compare the two.
    bool nativeDrawIndirectCount = true;
    // Compiled shaders and pipelines kept on disk (penumbra/rhi/PipelineCache.hpp); null: none, the default, so
    // that a library writes nowhere unasked. The tools pass one in the user's cache folder
    // (defaultPipelineCacheFolder()) unless PENUMBRA_PIPELINE_CACHE=off.
    std::shared_ptr<PipelineCache> pipelineCache;
    // A window to present to (Device::createSwapchain); none for offscreen devices. With one, an
    // OpenGL device takes its context from the window instead of a headless one.
    WindowDesc window;
};

// A configuration: a backend plus depth conventions under a name that every test, demo folder
// and command line uses ("vulkan", "opengl-noclip-reversed"). Each backend registers its own.
struct NamedConfiguration {
    std::string name;
    DeviceDesc desc;
};

} // namespace penumbra::rhi
