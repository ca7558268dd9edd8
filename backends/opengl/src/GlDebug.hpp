#pragma once

#include "penumbra/opengl/GlFunctions.hpp"

#include "penumbra/rhi/DebugMessageLog.hpp"

namespace penumbra::opengl {

// Turns on synchronous debug output on the current context, recording into `log`.
void enableDebugOutput(const GlFunctions& gl, rhi::DebugMessageLog& log);

} // namespace penumbra::opengl
