#version 450
// Shadow caster pass: light clip space, pancaked onto the near plane when the device has no depth clamp. In the
// caster-side normal bias mode the vertices move against their light-facing normal by the offset receivers would
// take (Unity's UnityClipSpaceShadowCasterPos; Catlike Coding, "Rendering 7: Shadows", section 2.1, Bias).

#include "instance.glsl"
#include "material.glsl"
#include "normal_offset.glsl"
#include "caster_block.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;

layout(location = 0) out vec2 vUv;

// Uniform values pick between results with mix(a, b, bool), a per-component select, never a branch: lavapipe (Mesa
// 22) inlines uniforms that decide branches into a freshly compiled shader whenever a draw's uniform block changes
// (lvp_execute.c, update_inline_shader_state), which cost about a millisecond and 135 KiB that are never freed per
// caster draw.
vec4 casterClip()
{
    const vec3 world = transformPoint(instanceModel(), inPosition).xyz;
    const vec4 plain = transformPoint(draw.viewProjection, world);
    const vec3 normal = normalize(instanceNormalMatrix() * inNormal);
    const bool positional = draw.light.w > 0.5;
    const vec3 towardsLight = mix(-draw.light.xyz, draw.light.xyz - world, bvec3(positional));
    const float distance = length(towardsLight);
    const float reach = draw.reach * mix(1.0, distance, positional);
    const vec4 moved =
        transformPoint(draw.viewProjection, world - receiverNormalOffset(normal, towardsLight / distance, reach));
    return mix(plain, moved, bvec4(draw.reach > 0.0));
}

void main()
{
    const vec4 clip = casterClip();
    gl_Position = mix(clip, penumbraClampToNearPlane(clip), bvec4(draw.pancake != 0));
    vUv = transformedUv(draw.baseColorUv, inUv, inUv1);
}
