#version 450
// Contact shadows (penumbra::render::ContactShadowPass): from each pixel's surface, rebuilt from the depth prepass
// through the inverse view-projection as the screen-space collection does, a short march towards each directional
// light through the same depth buffer; a sample whose ray point lies behind the depth there, by less than the
// surface's assumed thickness, is an occluder the shadow map may have missed (its texels, its biases). One channel
// per light, 1 = lit; the lit pass takes the minimum with the map's visibility on the light's direct term. After
// Bend Studio's "Bend Studio's screen space shadows" (Graham Aldridge, SIGGRAPH 2023 Advances) and Panos
// Karabelas's "Screen space shadows" (2019): steps along the light, a thickness band behind each depth sample, a
// per-pixel jitter of the first step. Screen and depth conventions are the RHI's (PENUMBRA_CLIP_TO_TEXTURE maps
// clip space to the texture coordinates of any render target, row 0 at the top; penumbraWindowDepthToNdc undoes the
// depth range), so no backend flips anything here.

#include "contact_constants.glsl" // the block Contact (penumbra::render::ContactShadowUniforms) and the bindings
#include "material.glsl"

layout(binding = PENUMBRA_BINDING_CONTACT_DEPTH) uniform sampler2D sceneDepth;

layout(location = 0) out vec4 outContact;

// View depth (metres along the camera's forward) of a depth-buffer value: z_ndc = b / d - a for the camera's
// projection (rhi::Conventions::viewDepth), reversed or not.
float viewDepthOf(float windowDepth)
{
    return contact.depthToView.y / (penumbraWindowDepthToNdc(windowDepth) + contact.depthToView.x);
}

float viewDepthAt(ivec2 pixel) { return viewDepthOf(texelFetch(sceneDepth, pixel, 0).r); }

// How far the surface's view depth moves over one pixel, the smaller one-sided difference on each axis (so that a
// neighbour across a silhouette does not count): a depth sample on the starting surface lies off the ray's own
// projection by up to a pixel, and must not read as an occluder.
float depthStepPerPixel(ivec2 pixel, float depth)
{
    const ivec2 last = ivec2(contact.targetSize.xy) - 1;
    const float left = abs(depth - viewDepthAt(clamp(pixel - ivec2(1, 0), ivec2(0), last)));
    const float right = abs(depth - viewDepthAt(clamp(pixel + ivec2(1, 0), ivec2(0), last)));
    const float up = abs(depth - viewDepthAt(clamp(pixel - ivec2(0, 1), ivec2(0), last)));
    const float down = abs(depth - viewDepthAt(clamp(pixel + ivec2(0, 1), ivec2(0), last)));
    return max(min(left, right), min(up, down));
}

// 1 where the march from `position` towards the light meets no occluder, 0 where it does. Projection and view depth
// are linear in clip space along the ray, so each step interpolates its ends instead of projecting anew.
float contactVisibility(vec3 position, ivec2 start, vec3 towardsLight, float bias, float jitter)
{
    const vec3 end = position + towardsLight * contact.marchLength;
    const mat4 toTexture = PENUMBRA_CLIP_TO_TEXTURE * contact.viewProjection;
    const vec4 startTexture = toTexture * vec4(position, 1.0);
    const vec4 endTexture = toTexture * vec4(end, 1.0);
    const float startDepth = dot(position - contact.cameraPosition.xyz, contact.cameraForward.xyz);
    const float endDepth = dot(end - contact.cameraPosition.xyz, contact.cameraForward.xyz);
    for (int i = 0; i < contact.steps; ++i) {
        const float t = (float(i) + jitter) / float(contact.steps);
        const vec4 projected = mix(startTexture, endTexture, t);
        const float rayDepth = mix(startDepth, endDepth, t);
        // Behind the near plane or off the picture: the depth buffer knows nothing further along.
        if (rayDepth <= contact.depthToView.z || projected.w <= 0.0)
            break;
        const vec2 uv = projected.xy / projected.w;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
            break;
        const ivec2 pixel = ivec2(uv * contact.targetSize.xy);
        const float depth = texelFetch(sceneDepth, pixel, 0).r;
        if (pixel == start || depth == PENUMBRA_FAR_DEPTH)
            continue;
        const float behind = rayDepth - viewDepthOf(depth);
        if (behind > bias && behind < bias + contact.thickness)
            return 0.0;
    }
    return 1.0;
}

void main()
{
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const float windowDepth = texelFetch(sceneDepth, pixel, 0).r;
    outContact = vec4(1.0);
    if (windowDepth == PENUMBRA_FAR_DEPTH)
        return;
    const vec2 ndc = penumbraFragCoordToNdc(gl_FragCoord.xy, contact.targetSize.xy);
    const vec4 world = contact.clipToWorld * vec4(ndc, penumbraWindowDepthToNdc(windowDepth), 1.0);
    const vec3 position = world.xyz / world.w;
    const float depth = viewDepthAt(pixel);
    // A pixel's worth of the surface's own depth slope, and a relative floor for the depth's rounding.
    const float bias = depthStepPerPixel(pixel, depth) + 1e-3 * depth;
    const float jitter = 0.5 + 0.5 * interleavedGradientNoise(gl_FragCoord.xy);
    for (int i = 0; i < contact.lightCount; ++i)
        outContact[i] = contactVisibility(position, pixel, contact.towardsLight[i].xyz, bias, jitter);
}
