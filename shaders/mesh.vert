#version 450
// A small mesh with its own transform: the draw-call benchmark's unit of work.

#include "constants.glsl"

layout(location = 0) in vec3 inPosition;

layout(std140, binding = PENUMBRA_BINDING_OBJECT) uniform Object {
    mat4 modelViewProjection;
    vec4 color;
} object;

layout(location = 0) out vec4 vColor;

void main()
{
    gl_Position = object.modelViewProjection * vec4(inPosition, 1.0);
    vColor = object.color;
}
