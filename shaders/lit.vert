#version 450

#include "instance.glsl"
#include "lit.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inTangent;
layout(location = 5) in vec4 inColor;

layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec2 vUv;
layout(location = 3) out vec2 vUv1;
layout(location = 4) out vec4 vTangent;
layout(location = 5) out vec4 vColor;

void main()
{
    const vec3 world = transformPoint(instanceModel(), inPosition).xyz;
    vPosition = world;
    vNormal = instanceNormalMatrix() * inNormal;
    vUv = inUv;
    vUv1 = inUv1;
    // Tangents follow the surface (the model matrix); a mirroring one reverses cross(normal, tangent), so the
    // handedness takes its sign.
    vTangent = vec4(mat3(instanceModel()) * inTangent.xyz, inTangent.w * instanceHandedness());
    vColor = inColor;
    gl_Position = cameraClipPosition(frame.viewProjection, instanceModel(), inPosition);
}
