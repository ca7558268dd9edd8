#pragma once

#include "penumbra/rhi/Shader.hpp"

#include <string_view>

namespace penumbra::shaders {

// The GLSL files of shaders/, embedded at build time. Unknown names throw rhi::Error listing the known ones.
std::string_view source(std::string_view fileName);

// A ShaderSource for a file, its stage taken from the extension (.vert, .frag); the .glsl files are its includes.
rhi::ShaderSource load(std::string_view fileName);

} // namespace penumbra::shaders
