#version 450
// The reference lit pass's vertices (penumbra::render::ReferenceLitPass): world position, normal and uv.

#include "instance.glsl"
#include "lit.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec2 vUv;

void main()
{
    const vec3 world = transformPoint(instanceModel(), inPosition).xyz;
    vPosition = world;
    vNormal = instanceNormalMatrix() * inNormal;
    vUv = inUv;
    gl_Position = transformPoint(frame.viewProjection, world);
}
