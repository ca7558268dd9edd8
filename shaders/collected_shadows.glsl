// The lit pass's side of the screen-space shadows (penumbra::render::ScreenSpaceShadowPass,
// DirectionalShadowSource): the attenuation of directional lights 0 .. PENUMBRA_COLLECTED_LIGHTS - 1 that the
// full-screen pass collected at this pixel for the surface the depth prepass left there. Needs lit.glsl first.

#if PENUMBRA_SCREEN_SPACE_SHADOWS
layout(binding = PENUMBRA_BINDING_SCREEN_SPACE_SHADOWS) uniform sampler2D screenSpaceShadows;

vec4 collectedShadows() { return texelFetch(screenSpaceShadows, ivec2(gl_FragCoord.xy), 0); }

// Lights past the collected ones have no shadows on this path (SceneRenderer draws such frames forward).
float collectedShadow(vec4 collected, int light) { return light < PENUMBRA_COLLECTED_LIGHTS ? collected[light] : 1.0; }
#endif

#if PENUMBRA_SCREEN_SPACE_SHADOWS == PENUMBRA_SCREEN_SPACE_EDGES
// The single-sampled depth the shadows were collected from: one surface per pixel, at the pixel centre.
layout(binding = PENUMBRA_BINDING_SCREEN_SPACE_DEPTH) uniform sampler2D screenSpaceDepth;

// Whether the collected surface at this pixel is this fragment's, so its shadow is this fragment's too. Without
// sample shading a fragment is shaded at the pixel centre (GL 4.5 section 15.2.2, Vulkan 1.3 section 28.4), where
// the collection looked. A fragment that covers every sample covers the centre (inside the samples' hull, and a
// triangle is convex); and where its depth there is the collected one, no other surface shows at the centre. Edge
// fragments (partial coverage: the document's MSAA pitfall, an edge pixel taking the shadow of the surface behind)
// are evaluated forward. The tolerance absorbs the rounding between the two rasterizations of one plane, relative
// to the depth as float depth spacing is.
bool collectedHere()
{
    const int every = (1 << PENUMBRA_LIT_SAMPLES) - 1;
    const float collected = texelFetch(screenSpaceDepth, ivec2(gl_FragCoord.xy), 0).r;
    return (gl_SampleMaskIn[0] & every) == every &&
           abs(collected - gl_FragCoord.z) <= 1e-6 * max(abs(collected), 1e-3);
}
#endif
