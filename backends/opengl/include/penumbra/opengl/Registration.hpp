#pragma once

#include "penumbra/rhi/Backend.hpp"

namespace penumbra::opengl {

// The OpenGL backend as the backends module registers it: "opengl" with the configurations
// opengl and opengl-reversed (glClipControl, depth [0, 1]) and opengl-noclip and
// opengl-noclip-reversed (depth [-1, 1]), created by createOpenGLDevice with EGL surfaceless.
rhi::BackendRegistration registration();

} // namespace penumbra::opengl
