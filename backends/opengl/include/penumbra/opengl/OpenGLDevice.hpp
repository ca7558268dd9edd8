#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>

namespace penumbra::opengl {

// An OpenGL 4.5 core device on a headless context (EGL surfaceless or OSMesa, per
// desc.glContext). Throws rhi::Error naming what is missing when no context can be made.
std::unique_ptr<rhi::Device> createOpenGLDevice(const rhi::DeviceDesc& desc);

} // namespace penumbra::opengl
