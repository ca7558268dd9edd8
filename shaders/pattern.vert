#version 450
// The test pattern: vertices in canonical NDC (y up) with a colour; z is a view depth in
// [near, far] turned into this convention's clip space by the projection of the block.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;

// The uniform block Pattern (`pattern`: projection), generated from apps/common/TestPattern's PatternUniforms.
#include "pattern_blocks.glsl"

layout(location = 0) out vec4 vColor;

void main()
{
    // x, y are NDC; w = view depth so the perspective divide gives them back unchanged.
    vec4 clip = pattern.projection * vec4(0.0, 0.0, -inPosition.z, 1.0);
    gl_Position = vec4(inPosition.xy * clip.w, clip.z, clip.w);
    vColor = inColor;
}
