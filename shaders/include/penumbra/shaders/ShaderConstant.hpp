#pragma once

#include <cstdint>
#include <string_view>

namespace penumbra::shaders {

// A number the C++ caller shares with a shader (a binding, an array's length), written once in C++:
// `#define PENUMBRA_<name> value`.
struct ShaderConstant {
    std::string_view name;
    std::int64_t value;
};

} // namespace penumbra::shaders
