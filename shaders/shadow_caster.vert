#version 450
// Shadow caster pass: light clip space, pancaked onto the near plane when the device has no depth clamp.

#include "material.glsl"
#include "shadow_caster.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;

layout(location = 0) out vec2 vUv;

void main()
{
    const vec4 clip = transformPoint(draw.worldToClip, inPosition);
    gl_Position = draw.material.w > 0.5 ? penumbraClampToNearPlane(clip) : clip;
    vUv = transformedUv(draw.baseColorUv, inUv, inUv1);
}
