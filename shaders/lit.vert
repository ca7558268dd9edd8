#version 450

#include "lit.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec2 vUv;

void main()
{
    const vec4 world = object.model * vec4(inPosition, 1.0);
    vPosition = world.xyz;
    vNormal = mat3(object.normalMatrix) * inNormal;
    vUv = inUv;
    gl_Position = frame.viewProjection * world;
}
