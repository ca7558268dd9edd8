// The lit pass's side of the contact shadows. Needs lit_constants.glsl and pixel_surface.glsl first.

#if PENUMBRA_CONTACT_SHADOWS
// The contact shadows (penumbra::render::ContactShadowPass) of directional lights 0 .. PENUMBRA_COLLECTED_LIGHTS - 1
// at this pixel, 1 = lit; with MSAA only where the fragment is the surface they were marched from, lit elsewhere
// (an edge pixel must not take the contact shadow of the surface behind or in front).
layout(binding = PENUMBRA_BINDING_CONTACT_SHADOWS) uniform sampler2D contactShadowTexture;

vec4 contactShadows()
{
#if PENUMBRA_LIT_SAMPLES > 1
    if (!pixelSurfaceHere())
        return vec4(1.0);
#endif
    return texelFetch(contactShadowTexture, ivec2(gl_FragCoord.xy), 0);
}

float contactShadow(vec4 contact, int light) { return light < PENUMBRA_COLLECTED_LIGHTS ? contact[light] : 1.0; }
#endif
