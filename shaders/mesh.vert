#version 450
// A small mesh with its own transform: the draw-call benchmark's unit of work.

layout(location = 0) in vec3 inPosition;

// The uniform block Object (`object`: modelViewProjection, color), generated from apps/penumbra/DrawScene's
// DrawObjectUniforms.
#include "mesh_blocks.glsl"

layout(location = 0) out vec4 vColor;

void main()
{
    gl_Position = object.modelViewProjection * vec4(inPosition, 1.0);
    vColor = object.color;
}
