// The lit pass's side of the contact shadows. Needs lit_constants.glsl and pixel_surface.glsl first.

#if PENUMBRA_CONTACT_SHADOWS
// The contact shadows (penumbra::render::ContactShadowPass) at this pixel, as bits set where occluded: x for
// directional lights 0 .. PENUMBRA_COLLECTED_LIGHTS - 1, y for the frame's contact local lights (LocalLight's
// contactBit); with MSAA only where the fragment is the surface they were marched from, none elsewhere (an edge
// pixel must not take the contact shadow of the surface behind or in front).
layout(binding = PENUMBRA_BINDING_CONTACT_SHADOWS) uniform sampler2D contactShadowTexture;

// The march ran at half resolution, texel q from pixel 2q (x: its inverse view depth, y: its step per pixel,
// z: a bit per occluded directional light, w: a bit per occluded contact local light). A pixel takes the answer of
// the marched pixel within one pixel of it on each axis (1, 2 or 4 of them) whose depth is nearest its own, if that
// one lies on its surface (within two of its steps per pixel, rounding aside), and none (lit) otherwise:
// nearest-depth upsampling (Jansen and Bavoil, "Fast rendering of opacity-mapped particles using DirectX 11
// tessellation and mixed resolutions", NVIDIA 2011, section 3.3), so a silhouette never hands the surface behind or
// in front its contact shadow.
ivec2 contactShadows()
{
#if PENUMBRA_LIT_SAMPLES > 1
    if (!pixelSurfaceHere())
        return ivec2(0);
#endif
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const ivec2 low = pixel >> 1;
    const ivec2 high = min((pixel + 1) >> 1, textureSize(contactShadowTexture, 0) - 1);
    // The inverse view depth, 1 / w_c (view_depth.glsl): the same in every depth convention.
    const float depth = gl_FragCoord.w;
    float nearest = -1.0;
    ivec2 occluded = ivec2(0);
    for (int k = 0; k < 4; ++k) {
        const ivec2 texel = ivec2(k % 2 == 0 ? low.x : high.x, k < 2 ? low.y : high.y);
        const vec4 marched = texelFetch(contactShadowTexture, texel, 0);
        const float apart = abs(marched.x - depth);
        if ((nearest < 0.0 || apart < nearest) && apart <= 2.0 * marched.y + 1e-6 * depth) {
            nearest = apart;
            occluded = ivec2(marched.zw);
        }
    }
    return occluded;
}

// Directional light `light`'s contact shadow, 1 = lit.
float contactShadow(ivec2 contact, int light)
{
    return light < PENUMBRA_COLLECTED_LIGHTS && (contact.x & (1 << light)) != 0 ? 0.0 : 1.0;
}

// A spot or point light's contact shadow by its bit (-1: none), 1 = lit.
float contactLocalShadow(ivec2 contact, int bit) { return bit >= 0 && (contact.y & (1 << bit)) != 0 ? 0.0 : 1.0; }
#endif
