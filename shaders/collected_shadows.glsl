// The lit pass's side of the screen-space shadows (penumbra::render::ScreenSpaceShadowPass,
// DirectionalShadowSource): the attenuation of directional lights 0 .. PENUMBRA_COLLECTED_LIGHTS - 1 that the
// full-screen pass collected at this pixel for the surface the depth prepass left there. Needs lit.glsl first.

#if PENUMBRA_SCREEN_SPACE_SHADOWS
layout(binding = PENUMBRA_BINDING_SCREEN_SPACE_SHADOWS) uniform sampler2D screenSpaceShadows;

vec4 collectedShadows() { return texelFetch(screenSpaceShadows, ivec2(gl_FragCoord.xy), 0); }

// Lights past the collected ones have no shadows on this path (SceneRenderer draws such frames forward).
float collectedShadow(vec4 collected, int light) { return light < PENUMBRA_COLLECTED_LIGHTS ? collected[light] : 1.0; }
#endif
