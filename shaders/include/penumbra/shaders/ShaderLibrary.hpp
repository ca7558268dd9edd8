#pragma once

#include "penumbra/rhi/Shader.hpp"
#include "penumbra/shaders/ShaderConstant.hpp"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

namespace penumbra::shaders {

// The GLSL files of shaders/, embedded at build time. Unknown names throw rhi::Error listing the known ones.
std::string_view source(std::string_view fileName);

// A ShaderSource for a file, its stage taken from the extension (.vert, .frag, .comp); the .glsl files are its
// includes.
rhi::ShaderSource load(std::string_view fileName);

// One `#define PENUMBRA_<name> value` line per constant.
std::string defineLines(std::initializer_list<ShaderConstant> constants);

// load(fileName) with the include "constants.glsl" of `constants`, which the file includes.
rhi::ShaderSource load(std::string_view fileName, std::initializer_list<ShaderConstant> constants);

} // namespace penumbra::shaders
