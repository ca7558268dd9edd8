#pragma once

// A full-screen triangle tinted by a uniform block (binding 0) times one texel of a sampled image (binding 1): the
// smallest draw that reads both a buffer and a texture, as binding-set tests need.
namespace penumbra::testing {

inline constexpr const char* kTintedImageVertexGlsl = R"(#version 450
const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
layout(std140, binding = 0) uniform Tint { vec4 color; } tint;
layout(location = 0) out vec4 color;
void main() { gl_Position = vec4(corners[gl_VertexIndex], 0.5, 1.0); color = tint.color; }
)";

inline constexpr const char* kTintedImageFragmentGlsl = R"(#version 450
layout(location = 0) in vec4 color;
layout(binding = 1) uniform sampler2D image;
layout(location = 0) out vec4 result;
void main() { result = color * texture(image, vec2(0.5)); }
)";

} // namespace penumbra::testing
