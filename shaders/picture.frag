#version 450
// Copies a picture onto the target with fullscreen.vert; v = 0 is the top row in both, so the
// picture keeps its orientation on every backend.

#include "constants.glsl"

layout(location = 1) in vec2 vUv;

layout(binding = PENUMBRA_BINDING_PICTURE) uniform sampler2D uPicture;

layout(location = 0) out vec4 outColor;

void main()
{
    outColor = texture(uPicture, vUv);
}
