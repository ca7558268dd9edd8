#version 450
// The screen-space shadow collection (penumbra::render::ScreenSpaceShadowPass): after the depth prepass, one
// full-screen pass turns each pixel's depth back into its world position through the inverse view-projection and
// evaluates the cascaded shadows of directional lights 0 .. PENUMBRA_COLLECTED_LIGHTS - 1 there as lit.frag does
// (cascade selection and its dither, fades, normal offset, each light's filter and the static maps), one channel per
// light, 1 = lit; the lit pass reads its pixel's (collected_shadows.glsl). The pixel-to-NDC and depth-to-NDC steps
// are the conventions' (penumbraFragCoordToNdc, penumbraWindowDepthToNdc): row 0 is the top and the depth range is
// the RHI's on every backend, so no backend flips anything here.

#include "lit_constants.glsl"
#include "screen_space_constants.glsl" // with the block Collection (penumbra::render::ScreenSpaceShadowUniforms)
#include "transform.glsl"
#include "shadow_filter.glsl"
#include "soft_shadows.glsl"
#include "directional_shadows.glsl"
#if PENUMBRA_STATIC_SHADOWS
#include "local_shadows.glsl"
#include "static_shadows.glsl"
#endif
#include "directional_light_shadow.glsl"
#include "material.glsl"

// The prepass's depth and its world position derivatives (receiver_prepass.frag), read with texelFetch.
layout(binding = PENUMBRA_BINDING_COLLECTION_DEPTH) uniform sampler2D sceneDepth;
layout(binding = PENUMBRA_BINDING_COLLECTION_POSITION_DX) uniform sampler2D positionDx;
layout(binding = PENUMBRA_BINDING_COLLECTION_POSITION_DY) uniform sampler2D positionDy;

layout(location = 0) out vec4 outShadows;

void main()
{
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const float depth = texelFetch(sceneDepth, pixel, 0).r;
    outShadows = vec4(1.0);
    // Nothing drawn here: the cleared far depth, whose position (at infinity with reversed-Z and an infinite far
    // plane) is never divided out.
    if (depth == PENUMBRA_FAR_DEPTH)
        return;
    const vec2 ndc = penumbraFragCoordToNdc(gl_FragCoord.xy, collection.targetSize.xy);
    const vec4 world = collection.clipToWorld * vec4(ndc, penumbraWindowDepthToNdc(depth), 1.0);
    const vec3 position = world.xyz / world.w;
    const vec3 dx = texelFetch(positionDx, pixel, 0).xyz;
    const vec3 dy = texelFetch(positionDy, pixel, 0).xyz;
    // lit.frag's geometric normal and receiver plane, from the same derivatives.
    const vec3 geometric = normalize(cross(dx, dy));
    setReceiverDerivatives(dx, dy);
    const float viewDepth = -dot(collection.cameraPosition.xyz - position, collection.cameraForward.xyz);
    const float dither = interleavedGradientNoise(gl_FragCoord.xy);
    const CascadeSelection cascade = selectCascade(0, position, viewDepth, dither);
    for (int i = 0; i < collection.lightCount; ++i) {
        const vec3 l = -collection.lights[i].direction;
        const int slot = collection.lights[i].shadowSlot;
        const CascadeSelection lightCascade = selectLightCascade(cascade, slot, position, viewDepth, dither);
        outShadows[i] = directionalLightShadow(i, slot, true, lightCascade, position, geometric, l);
    }
}
