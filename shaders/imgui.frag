#version 450
// Dear ImGui's fragments: vertex colour times the texture (the font atlas or a picture).

#include "constants.glsl"

layout(location = 0) in vec2 vUv;
layout(location = 1) in vec4 vColor;

layout(binding = PENUMBRA_BINDING_TEXTURE) uniform sampler2D uTexture;

layout(location = 0) out vec4 outColor;

void main()
{
    outColor = vColor * texture(uTexture, vUv);
}
