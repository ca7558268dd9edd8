#version 450
#include "colour.glsl"
layout(location = 0) out vec4 outColor;
layout(set = 0, binding = 1) uniform sampler2D picture;
void main() { outColor = tint(texture(picture, gl_FragCoord.xy)); }
//@include colour.glsl
layout(set = 0, binding = 0) uniform Tint { vec4 factor; } tintBlock;
vec4 tint(vec4 c) { return c * tintBlock.factor; }
