#version 450
// The reference lit pass (penumbra::render::ReferenceLitPass): the fragment shader of the public cascaded shadow
// map samples (Sascha Willems' Vulkan examples, "shadowmappingcascade", scene.frag): one base colour sample with
// an alpha test at 0.5, the cascade whose split the view depth has not passed, one depth comparison in it (nearest
// texelFetch: lavapipe cannot filter depth comparisons), Lambert n.l of one light plus ambient.

#include "transform.glsl"
#include "shadow_filter.glsl"
#include "soft_shadows.glsl"
#include "directional_shadows.glsl"
#include "lit.glsl"
#include "reference_block.glsl"

layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;

layout(location = 0) out vec4 outColor;

void main()
{
    const vec4 color = texture(baseColorMap, vUv) * object.baseColor;
    if (color.a < 0.5)
        discard;
    const float viewDepth = dot(vPosition - frame.cameraPosition.xyz, frame.cameraForward.xyz);
    const int count = reference.cascadeCount;
    int cascade = 0;
    for (int i = 0; i < count - 1; ++i)
        if (viewDepth > reference.farDepths[i])
            cascade = i + 1;
    float shadow = 1.0;
    if (reference.firstTile >= 0 && count > 0 && viewDepth < reference.farDepths[count - 1]) {
        const vec3 p = transformPoint(shadows.worldToAtlas[reference.firstTile + cascade], vPosition).xyz;
        shadow = compareTexel(shadowAtlas, ivec2(p.xy * shadows.atlasSize), p.z);
    }
    const vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
    const float nl = max(dot(n, -frame.lights[0].direction), 0.0);
    outColor = vec4(color.rgb * (frame.ambient.rgb + frame.lights[0].color * nl * shadow), 1.0);
}
