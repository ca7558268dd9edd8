#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>

namespace penumbra::opengl {

// How an OpenGL device gets a context without a window.
enum class ContextProvider { EglSurfaceless, OSMesa };

// What only an OpenGL device is created with, beside the API-neutral rhi::DeviceDesc.
struct OpenGLDeviceOptions {
    // Ignored when DeviceDesc::window is set: the window's context is used.
    ContextProvider context = ContextProvider::EglSurfaceless;
};

// An OpenGL 4.5 core device on a headless context (options.context) or on desc.window's.
// desc.depthRange ZeroToOne uses glClipControl (depth [0, 1], upper-left origin); MinusOneToOne
// takes the path of drivers without clip control: depth [-1, 1] and a vertex-stage Y flip.
// Throws rhi::Error naming what is missing when no context can be made.
std::unique_ptr<rhi::Device> createOpenGLDevice(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options = {});

} // namespace penumbra::opengl
