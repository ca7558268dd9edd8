#version 450
// Image-based lighting from the frame's environment (environment_light.glsl), or an ambient hemisphere without one, then
// Lambert diffuse plus GGX specular for up to 8 directional lights (4 with shadows), each attenuated by its
// cascaded shadow, and every spot and point light whose cluster list holds the fragment's cluster, with their atlas
// shadows; clip materials are cut
// with the same alpha as their shadows. glTF 2.0 metallic-roughness materials (section 3.9): factors times
// textures, vertex colours, normal, occlusion and emissive textures, KHR_materials_unlit.

#include "transform.glsl"
#include "shadow_filter.glsl"
#include "soft_shadows.glsl"
#include "directional_shadows.glsl"
#include "local_shadows.glsl"
#include "static_shadows.glsl"
#include "lit.glsl"
#include "local_lights.glsl"
#include "directional_light_shadow.glsl"
#include "material.glsl"
#include "collected_shadows.glsl"
#include "pixel_surface.glsl"
#include "contact_shadows_lit.glsl"
#include "environment_light.glsl"

layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;
layout(location = 3) in vec2 vUv1;
layout(location = 4) in vec4 vTangent;
layout(location = 5) in vec4 vColor;

layout(location = 0) out vec4 outColor;

const float PI = 3.14159265;

// Karis 2013, "Real Shading in Unreal Engine 4": GGX distribution, height-correlated Smith
// visibility (Heitz 2014) and Schlick's Fresnel. The dielectric's diffuse takes the light its specular layer does not
// reflect (glTF 2.0 specification, Appendix B.3.5: the dielectric is mix(diffuse, specular, F) with f0 = 0.04); Schlick
// is linear in f0, so one Fresnel of the mixed f0 gives both layers' specular.
vec3 brdf(vec3 n, vec3 v, vec3 l, vec3 base, float metallic, float roughness)
{
    const vec3 h = normalize(v + l);
    const float nl = max(dot(n, l), 0.0);
    const float nv = max(dot(n, v), 1e-4);
    const float nh = max(dot(n, h), 0.0);
    const float a = roughness * roughness;
    const float a2 = a * a;
    const float d = nh * nh * (a2 - 1.0) + 1.0;
    const float distribution = a2 / (PI * d * d);
    const float visibility = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    const float schlick = pow(1.0 - max(dot(v, h), 0.0), 5.0);
    const vec3 f0 = mix(vec3(0.04), base, metallic);
    const vec3 fresnel = f0 + (1.0 - f0) * schlick;
    const vec3 diffuse = (1.0 - metallic) * (1.0 - (0.04 + 0.96 * schlick)) * base / PI;
    return diffuse + distribution * visibility * fresnel;
}

vec3 linearToSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Smallest roughness the GGX terms take: at 0 the distribution is a Dirac peak (0 / 0 at n = h).
const float MIN_ROUGHNESS = 0.03;

// An absent map reads as its white stand-in texel would.
vec4 sampleMap(sampler2D map, int slot)
{
    return hasMap(slot) ? texture(map, transformedUv(uvRows(slot), vUv, vUv1)) : vec4(1.0);
}

// The front face's shading normal: the interpolated normal, perturbed by the normal texture in the tangent frame
// (glTF 2.0 section 3.9.3: bitangent = w * cross(normal, tangent), x and y scaled by normalTexture.scale).
vec3 frontNormal()
{
    const vec3 n = normalize(vNormal);
    if (!hasMap(PENUMBRA_TEXTURE_NORMAL))
        return n;
    const vec3 t = normalize(vTangent.xyz - n * dot(n, vTangent.xyz));
    const vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 mapped = sampleMap(normalMap, PENUMBRA_TEXTURE_NORMAL).xyz * 2.0 - 1.0;
    mapped.xy *= object.normalScale;
    return normalize(mat3(t, b, n) * mapped);
}

const vec3 cascadeColors[5] = vec3[](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.25, 0.4, 1.0),
                                     vec3(1.0, 1.0, 0.25), vec3(0.5, 0.5, 0.5));

// Local light i's static map: its first tile or -1, its strength.
StaticLocalLightMap staticLocalLightMap(int i)
{
    return StaticLocalLightMap(int(localLightStaticTile(i)), localLightStaticStrength(i));
}

// Spot or point light i at the fragment: its fields (localLight* of local_light_record.glsl), direction towards it
// and the light that arrives before N.L.
struct LocalLight {
    vec3 position;
    vec3 color;
    vec3 axis;
    int shadowTile;
    float shadowStrength;
    vec3 l;
    float falloff;
    bool isPoint;
    int contactBit; // its bit in the contact shadow texture (contactLocalShadow), -1 without contact shadows
};

LocalLight localLight(int i)
{
    LocalLight result;
    result.position = localLightPosition(i);
    result.color = localLightColor(i);
    result.axis = localLightAxis(i);
    result.contactBit = int(localLightContactBit(i));
    result.shadowTile = int(localLightShadowTile(i));
    result.shadowStrength = localLightShadowStrength(i);
    const float inverseRangeSquared = localLightInverseRangeSquared(i);
    const vec3 toLight = result.position - vPosition;
    const float d2 = max(dot(toLight, toLight), 1e-5);
    result.l = toLight * inversesqrt(d2);
    result.isPoint = int(localLightKind(i)) == PENUMBRA_LIGHT_POINT;
    // Smooth range window over inverse-square falloff (Karis 2013, "Real Shading in Unreal Engine 4", section
    // "Lights"), then the spot cone's smooth step between outer and inner angle.
    const float window =
        clamp(1.0 - d2 * inverseRangeSquared * d2 * inverseRangeSquared, 0.0, 1.0);
    const float cone = result.isPoint ? 1.0
                                      : clamp(dot(result.axis, -result.l) * localLightConeScale(i) +
                                                  localLightConeOffset(i),
                                              0.0, 1.0);
    result.falloff = window * window / d2 * cone * cone;
    return result;
}

// The visibility view: the raw filtered shadow of light `index` (directional lights first, then spot and point
// lights) in red, green and blue, and in alpha whether that shadow map decides the pixel (1) or not (0: the
// light does not reach it, it has no shadow there, or the material receives none).
vec4 shadowVisibility(int index, vec3 n, vec3 geometric, CascadeSelection cascade, float globalStrength)
{
    const bool receives = object.receivesShadows != 0;
    if (index < frame.directionalLightCount) {
        const int slot = receives ? frame.lights[index].shadowSlot : -1;
        const StaticDirectionalLight map = staticShadows.directionalLights[index];
        const bool realtime = directionalShadowReaches(slot, cascade);
        const bool fromStatic = receives && map.tile >= 0;
        if (dot(n, -frame.lights[index].direction) <= 0.0 || !(realtime || fromStatic))
            return vec4(1.0, 1.0, 1.0, 0.0);
        const vec3 towardsLight = -frame.lights[index].direction;
        float shadow = realtime ? directionalShadowVisibility(slot, cascade, vPosition, geometric, towardsLight) : 1.0;
#if PENUMBRA_CONTACT_SHADOWS
        shadow = min(shadow, contactShadow(contactShadows(), index));
#endif
        return vec4(vec3(fromStatic ? min(shadow, staticDirectionalVisibility(map, vPosition, geometric, towardsLight))
                                    : shadow),
                    1.0);
    }
    const int i = index - frame.directionalLightCount;
    const LocalLight light = localLight(i);
    const StaticLocalLightMap map = staticLocalLightMap(i);
    const bool realtime = light.shadowTile >= 0 && globalStrength > 0.0;
    const bool fromStatic = map.tile >= 0;
    if (!receives || dot(n, light.l) <= 0.0 || light.falloff <= 0.0 || !(realtime || fromStatic))
        return vec4(1.0, 1.0, 1.0, 0.0);
    const vec3 lightPosition = light.position;
    const vec3 axis = light.axis;
    float visibility =
        realtime ? localShadowVisibility(light.shadowTile, light.isPoint, lightPosition, axis, vPosition, geometric)
                 : 1.0;
#if PENUMBRA_CONTACT_SHADOWS
    visibility = min(visibility, contactLocalShadow(contactShadows(), light.contactBit));
#endif
    return vec4(vec3(fromStatic ? min(visibility, staticLocalVisibility(map.tile, light.isPoint, lightPosition, axis,
                                                                        vPosition, geometric))
                                : visibility),
                1.0);
}

void main()
{
    const int casterMode = object.casterMode;
    const bool textured = hasMap(PENUMBRA_TEXTURE_BASE_COLOR);
    const vec2 baseUv = transformedUv(uvRows(PENUMBRA_TEXTURE_BASE_COLOR), vUv, vUv1);
    const vec4 texel = textured ? texture(baseColorMap, baseUv) : vec4(1.0);
#if PENUMBRA_DEPTH_PREPASSED
    // After a depth prepass the equal depth test has already cut clip holes (depth_prepass_clip.frag): no discard
    // here keeps early depth testing on, so each visible pixel is shaded once. Blended surfaces are drawn without it.
    const float coverage = 1.0;
#else
    const float textureAlpha = textured ? texture(coverageMap, baseUv).a : 1.0;
    const float alpha = materialAlpha(object.baseColor.a, casterMode, baseUv, textured, textureAlpha) * vColor.a;
    if (casterMode == PENUMBRA_CASTER_CLIP && alpha < object.alphaCutoff)
        discard;
    // Blended surfaces cover by their alpha; everything else is opaque.
    const float coverage = object.blended != 0 ? alpha : 1.0;
#endif

    // Base colour textures are RGBA8_SRGB: sampling has decoded them to linear light before filtering.
    const vec3 base = object.baseColor.rgb * vColor.rgb * (textured ? texel.rgb : vec3(1.0));
    // Unlit surfaces show no shadow: the visibility view leaves them undecided.
    if (object.unlit != 0) {
        outColor = PENUMBRA_LIT_VIEW == PENUMBRA_VIEW_VISIBILITY ? vec4(1.0, 1.0, 1.0, 0.0)
                                                                 : vec4(linearToSrgb(base), coverage);
        return;
    }
    // Back faces (of double-sided materials, or seen through clip holes) are shaded with the flipped normal.
    const vec3 front = frontNormal();
    const vec3 n = gl_FrontFacing ? front : -front;
    // The triangle's plane, for the shadows' normal offset (its sign does not matter: it is turned to each light).
    const vec3 geometric = normalize(cross(dFdxFine(vPosition), dFdyFine(vPosition)));
    setReceiverDerivatives(dFdxFine(vPosition), dFdyFine(vPosition));
    const vec3 toCamera = frame.cameraPosition.xyz - vPosition;
    const vec3 v = normalize(toCamera);
    const float viewDepth = -dot(toCamera, frame.cameraForward.xyz);
    // The first shadowed light's selection; depth fit selects again for each other light (selectLightCascade).
    const float dither = interleavedGradientNoise(gl_FragCoord.xy);
    const CascadeSelection cascade = selectCascade(0, vPosition, viewDepth, dither);
    const float globalStrength = fadedShadowStrength(viewDepth, shadows.fade.inverseMaxDistance, shadows.fade.inverseDistanceFade);
#if PENUMBRA_LIT_VIEW == PENUMBRA_VIEW_VISIBILITY
    const int visibilitySlot =
        frame.visibilityLight < frame.directionalLightCount ? frame.lights[frame.visibilityLight].shadowSlot : -1;
    outColor = shadowVisibility(frame.visibilityLight, n, geometric,
                                selectLightCascade(cascade, visibilitySlot, vPosition, viewDepth, dither),
                                globalStrength);
#else

    const vec4 metalRough = sampleMap(metallicRoughnessMap, PENUMBRA_TEXTURE_METALLIC_ROUGHNESS);
    const float metallic = object.metallic * metalRough.b;
    const float roughness = max(object.roughness * metalRough.g, MIN_ROUGHNESS);
    const float occlusion = 1.0 + object.occlusionStrength * (sampleMap(occlusionMap, PENUMBRA_TEXTURE_OCCLUSION).r - 1.0);
    // The environment's diffuse and specular light, which shadows do not darken; without one, a sky/ground
    // hemisphere: the ambient colour from above, the ground colour from below.
    const vec3 ambient = mix(frame.ambientGround.rgb, frame.ambient.rgb, 0.5 + 0.5 * n.y);
    vec3 color = hasEnvironment() ? environmentLight(n, v, base, metallic, roughness, occlusion)
                                  : ambient * base * occlusion;
#if PENUMBRA_SCREEN_SPACE_SHADOWS
    const vec4 collected = collectedShadows();
#endif
#if PENUMBRA_SCREEN_SPACE_SHADOWS == PENUMBRA_SCREEN_SPACE_EDGES
    const bool fromCollection = pixelSurfaceHere();
#endif
#if PENUMBRA_CONTACT_SHADOWS
    const ivec2 contact = contactShadows();
#endif
    for (int i = 0; i < frame.directionalLightCount; ++i) {
        const vec3 l = -frame.lights[i].direction;
        const float nl = dot(n, l);
        if (nl <= 0.0)
            continue;
        const bool receives = object.receivesShadows != 0;
        const int slot = receives ? frame.lights[i].shadowSlot : -1;
        const CascadeSelection lightCascade =
            selectLightCascade(cascade, frame.lights[i].shadowSlot, vPosition, viewDepth, dither);
#if PENUMBRA_SCREEN_SPACE_SHADOWS == PENUMBRA_SCREEN_SPACE_PIXELS
        const float attenuation = receives ? collectedShadow(collected, i) : 1.0;
#elif PENUMBRA_SCREEN_SPACE_SHADOWS == PENUMBRA_SCREEN_SPACE_EDGES
        const float attenuation = fromCollection ? (receives ? collectedShadow(collected, i) : 1.0)
                                                 : directionalLightShadow(i, slot, receives, lightCascade, vPosition,
                                                                          geometric, l);
#else
        const float attenuation = directionalLightShadow(i, slot, receives, lightCascade, vPosition, geometric, l);
#endif
#if PENUMBRA_CONTACT_SHADOWS
        // Contact shadows darken the direct light only, as the map's shadow does: the minimum, so that a pixel both
        // cover is not darkened twice.
        const float visible = min(attenuation, receives ? contactShadow(contact, i) : 1.0);
#else
        const float visible = attenuation;
#endif
        color += brdf(n, v, l, base, metallic, roughness) * frame.lights[i].color * nl * visible;
    }
#if PENUMBRA_LOCAL_LIGHTS
    // The cluster's lights in ascending index, as a loop over every light would add them: a light left out of the
    // list reaches no point of the cluster, so it would add nothing.
    const ivec2 list = clusterLightList(vPosition);
    for (int entry = list.x; entry < list.x + list.y; ++entry) {
        const int i = clusterLight(entry);
        const LocalLight light = localLight(i);
        const float nl = dot(n, light.l);
        if (nl <= 0.0 || light.falloff <= 0.0)
            continue;
        const bool receives = object.receivesShadows != 0;
#if PENUMBRA_STATIC_SHADOWS
        const float attenuation =
            localAttenuation(staticLocalLightMap(i), light.shadowTile, light.shadowStrength, receives, light.isPoint,
                             light.position, light.axis, vPosition, geometric, globalStrength);
#else
        const float attenuation =
            receives ? localShadowAttenuation(light.shadowTile, light.shadowStrength, light.isPoint, light.position,
                                              light.axis, vPosition, geometric, globalStrength)
                     : 1.0;
#endif
#if PENUMBRA_CONTACT_SHADOWS
        // As a directional light's, the minimum with the map's shadow; faded by the light's shadow strength as its map
        // is (the frame's few nearest shadowed lights have a bit, contactLocalLights; the others none).
        const float visible = min(attenuation, receives ? mix(1.0, contactLocalShadow(contact, light.contactBit),
                                                              light.shadowStrength)
                                                        : 1.0);
#else
        const float visible = attenuation;
#endif
        color += brdf(n, v, light.l, base, metallic, roughness) * light.color * nl * light.falloff * visible;
    }
#endif
    // Emissive textures are RGBA8_SRGB too: already linear when sampled.
    color += object.emissive * sampleMap(emissiveMap, PENUMBRA_TEXTURE_EMISSIVE).rgb;
#if PENUMBRA_LIT_VIEW == PENUMBRA_VIEW_CASCADES
    color = mix(color, cascadeColors[min(cascade.index, 4)] * 0.8, 0.6);
#endif
    outColor = vec4(linearToSrgb(color), coverage);
#endif
}
