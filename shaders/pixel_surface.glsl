// Whether this fragment's surface is the one a single-sampled screen-space pass saw at its pixel (the screen-space
// shadow collection with MSAA, DirectionalShadowSource::ScreenSpaceEdges, and the contact shadows with MSAA), so
// that pass's value at the pixel is this fragment's too. Needs lit_constants.glsl (PENUMBRA_PIXEL_DEPTH) first.

#if PENUMBRA_PIXEL_DEPTH
// The single-sampled depth those passes read: one surface per pixel, at the pixel centre.
layout(binding = PENUMBRA_BINDING_SCREEN_SPACE_DEPTH) uniform sampler2D screenSpaceDepth;

// Without sample shading a fragment is shaded at the pixel centre (GL 4.5 section 15.2.2, Vulkan 1.3 section 28.4),
// where those passes looked. A fragment that covers every sample covers the centre (inside the samples' hull, and a
// triangle is convex); and where its depth there is the single-sampled one, no other surface shows at the centre.
// Edge fragments (partial coverage: the document's MSAA pitfall, an edge pixel taking the shadow of the surface
// behind) are not. The tolerance absorbs the rounding between the two rasterizations of one plane, relative to the
// depth as float depth spacing is.
bool pixelSurfaceHere()
{
    const int every = (1 << PENUMBRA_LIT_SAMPLES) - 1;
    const float collected = texelFetch(screenSpaceDepth, ivec2(gl_FragCoord.xy), 0).r;
    return (gl_SampleMaskIn[0] & every) == every &&
           abs(collected - gl_FragCoord.z) <= 1e-6 * max(abs(collected), 1e-3);
}
#endif
