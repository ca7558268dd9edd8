#version 450
// Contact shadows (penumbra::render::ContactShadowPass): from every other pixel's surface (half resolution), rebuilt
// from its view depth along the ray through the pixel's centre, a short march towards each directional light, and
// towards the position of each of a few spot and point lights chosen per frame (penumbra::render::contactLocalLights),
// through the same view depths; a sample whose ray point lies behind the surface there, by less than the surface's
// assumed thickness, is an occluder the shadow map may have missed (its texels, its biases). One bit per light; the
// lit pass upsamples them and takes the minimum with the map's visibility on the light's direct term. After Bend
// Studio's "Bend Studio's screen space shadows" (Graham Aldridge, SIGGRAPH 2023 Advances) and Panos Karabelas's
// "Screen space shadows" (2019): steps along the light, a thickness band behind each depth sample, a per-pixel jitter
// of the first step. The march reads the prepass's view depth (view_depth.glsl), not the depth buffer: every depth
// convention rounds the depth buffer differently, and a sample within that rounding of the bias would decide
// otherwise in each configuration. Screen conventions are the RHI's (Conventions::clipToTexture in worldToTexture maps
// clip space to the texture coordinates of any render target, row 0 at the top; its z row is unused here), so no
// backend flips anything.

#include "contact_constants.glsl" // the block Contact (penumbra::render::ContactShadowUniforms) and the bindings
#include "material.glsl"

// The prepass's view depth (view_depth.glsl), metres along the camera's forward, negated on alpha-tested surfaces;
// 0 where no surface was drawn.
layout(binding = PENUMBRA_BINDING_CONTACT_DEPTH) uniform sampler2D sceneViewDepth;

layout(location = 0) out vec4 outContact;

// The surface's view depth, alpha-tested or not (view_depth.glsl: those are negated).
float viewDepthAt(ivec2 pixel)
{
    return abs(texelFetch(sceneViewDepth, clamp(pixel, ivec2(0), ivec2(contact.targetSize.xy) - 1), 0).r);
}

// 1 / view depth, 0 where no surface was drawn (infinitely far, as the depth buffer's far value).
float inverseViewDepth(float depth) { return depth > 0.0 ? 1.0 / depth : 0.0; }

// How far a depth moves over one pixel, the smaller one-sided difference on each axis (so that a neighbour across a
// silhouette does not count), for the surface's depths `here` and its four neighbours.
float stepPerPixel(float here, float left, float right, float up, float down)
{
    return max(min(abs(here - left), abs(here - right)), min(abs(here - up), abs(here - down)));
}

// Whether the march of `marchLength` metres from `position` towards the light meets an occluder. The march runs in
// the frame's pixels times clip w: x / w and y / w are the pixel, w itself is the view depth (clipToTexture keeps w,
// and every convention's perspective puts the view depth there). All three are linear along the ray, so each step
// adds a fixed increment instead of projecting anew, and one reciprocal of w gives the pixel.
bool contactOccluded(vec3 position, ivec2 start, vec3 towardsLight, float marchLength, float bias, float jitter)
{
    const vec3 toPixels = vec3(contact.targetSize.xy, 1.0);
    const vec3 first = (contact.worldToTexture * vec4(position, 1.0)).xyw * toPixels;
    const vec3 last = (contact.worldToTexture * vec4(position + towardsLight * marchLength, 1.0)).xyw * toPixels;
    const vec3 increment = (last - first) / float(contact.steps);
    vec3 projected = first + jitter * increment;
    // Whether the last sample lay on a card and in front of it.
    bool beforeCard = false;
    // A do-while, as the lights' loop in main() (see there): steps >= 1 (ContactShadowSettings).
    int i = 0;
    do {
        // Behind the near plane or off the picture: the depth buffer knows nothing further along.
        if (projected.z <= contact.nearPlane)
            break;
        const vec2 point = projected.xy * (1.0 / projected.z);
        if (any(lessThan(point, vec2(0.0))) || any(greaterThanEqual(point, contact.targetSize.xy)))
            break;
        const ivec2 pixel = ivec2(point);
        const float sampled = texelFetch(sceneViewDepth, pixel, 0).r;
        const float behind = projected.z - abs(sampled);
        // An alpha-tested surface (negated, view_depth.glsl) is a card without thickness: it occludes where the ray
        // crosses it, from in front of a card at the last sample to behind one within this step, not in the whole
        // band behind it.
        const bool card = sampled < 0.0;
        const float band = card ? (beforeCard ? min(contact.thickness, abs(increment.z)) : 0.0) : contact.thickness;
        // The starting pixel's own depth and no surface (view depth 0) are no occluders.
        if (behind > bias && behind < bias + band && sampled != 0.0 && pixel != start)
            return true;
        beforeCard = card && behind <= bias;
        projected += increment;
    } while (++i < contact.steps);
    return false;
}

// Half resolution: texel q marches from the full-resolution pixel 2q and keeps what the lit pass needs to hand its
// answer to the pixels around it (contact_shadows_lit.glsl): that pixel's inverse view depth, its step per pixel, a
// bit per directional light and a bit per spot or point light that the march found occluded.
void main()
{
    const ivec2 pixel = 2 * ivec2(gl_FragCoord.xy);
    const float depth = viewDepthAt(pixel);
    outContact = vec4(depth, 0.0, 0.0, 0.0);
    if (depth <= 0.0)
        return;
    const vec2 centre = vec2(pixel) + 0.5;
    const vec2 ndc = penumbraFragCoordToNdc(centre, contact.targetSize.xy);
    const vec3 position = contact.cameraPosition.xyz +
                          depth * (contact.cameraForward.xyz + ndc.x * contact.viewRayRight.xyz +
                                   ndc.y * contact.viewRayUp.xyz);
    // A pixel's worth of the surface's own view depth slope (a depth sample on the starting surface lies off the
    // ray's own projection by up to a pixel, and must not read as an occluder), and a relative floor for the depths'
    // rounding.
    const float left = viewDepthAt(pixel - ivec2(1, 0)), right = viewDepthAt(pixel + ivec2(1, 0));
    const float up = viewDepthAt(pixel - ivec2(0, 1)), down = viewDepthAt(pixel + ivec2(0, 1));
    const float bias = stepPerPixel(depth, left, right, up, down) + 1e-3 * depth;
    // For the upsampling, the inverse view depth (gl_FragCoord.w there), which is linear in screen space as window
    // depth is: on a plane the odd pixel between two marched ones lies exactly between them, and a step per pixel
    // measures the plane alike on both sides.
    const float inverse = 1.0 / depth;
    outContact.xy = vec2(inverse, stepPerPixel(inverse, inverseViewDepth(left), inverseViewDepth(right),
                                               inverseViewDepth(up), inverseViewDepth(down)));
    const float jitter = 0.5 + 0.5 * interleavedGradientNoise(centre);
    // One loop over the directional lights and then the chosen spot and point lights, so that the march is one
    // piece of code, and a do-while (the pass runs only for a frame with a light to march towards). llvmpipe and
    // lavapipe run control flow under lane masks: an `if` runs both sides, and a loop tests at its end whether any
    // lane is left (lp_exec_endloop, Mesa's src/gallium/auxiliary/gallivm/lp_bld_ir_common.c), so a loop whose
    // condition fails at the top runs its body once more, masked, and a loop of no iteration runs it once: a loop
    // per kind of light cost every pixel two more march set-ups and steps (docs/notes/2026-12-07-contact-cost.md).
    ivec2 occluded = ivec2(0);
    int light = 0;
    do {
        const bool directional = light < contact.lightCount;
        // A spot or point light: towards its position, no farther than the light itself, and only where it shines
        // (within its range and cone), since the lit pass adds nothing of it elsewhere. Its index is clamped so that
        // the directional lights' passes, which compute it too (both sides of a select), read inside the block.
        const int k = max(light - contact.lightCount, 0);
        const vec3 toLight = contact.localPosition[k].xyz - position;
        const float distance = length(toLight);
        const vec3 towardsLocal = toLight / max(distance, 1e-6);
        const bool shines = directional || (distance * distance * contact.localPosition[k].w < 1.0 &&
                                            dot(contact.localCone[k].xyz, -towardsLocal) > contact.localCone[k].w);
        const int d = min(light, contact.towardsLight.length() - 1); // inside the array in a masked pass
        const vec3 towardsLight = directional ? contact.towardsLight[d].xyz : towardsLocal;
        const float marchLength = directional ? contact.marchLength : min(contact.marchLength, distance);
        if (shines && contactOccluded(position, pixel, towardsLight, marchLength, bias, jitter)) {
            if (directional)
                occluded.x |= 1 << light;
            else
                occluded.y |= 1 << k;
        }
    } while (++light < contact.lightCount + contact.localLightCount);
    outContact.zw = vec2(occluded);
}
