#version 450
// The depth prepass (penumbra::render::DepthPrepass): the lit pass's clip position, and what its alpha test reads.

#include "instance.glsl"
#include "lit.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

layout(location = 2) out vec2 vUv;
layout(location = 3) out vec2 vUv1;
layout(location = 5) out vec4 vColor;

void main()
{
    vUv = inUv;
    vUv1 = inUv1;
    vColor = inColor;
    gl_Position = cameraClipPosition(frame.viewProjection, instanceModel(), inPosition);
}
