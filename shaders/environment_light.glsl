// Image-based lighting in the lit pass (render::EnvironmentLight): diffuse from nine spherical harmonics
// (frame.environmentSh, render::diffuseShaderCoefficients), specular from the prefiltered equirectangular chain and
// the split-sum BRDF table (Karis 2013, "Real Shading in Unreal Engine 4") with multiple scattering.
// frame.environmentCos and environmentSin: the rotation about +y; environmentLastLevel: the chain's last level (0
// without an environment).

#include "environment.glsl"

layout(binding = PENUMBRA_BINDING_ENVIRONMENT_SPECULAR) uniform sampler2D environmentSpecular;
layout(binding = PENUMBRA_BINDING_ENVIRONMENT_BRDF) uniform sampler2D environmentBrdf; // r = A, g = B

bool hasEnvironment() { return frame.environmentLastLevel > 0.0; }

// A world direction in the environment's frame: the environment is turned by the rotation about +y.
vec3 toEnvironment(vec3 d)
{
    const float c = frame.environmentCos;
    const float s = frame.environmentSin;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// Lambertian radiance per unit albedo at normal n (Ramamoorthi and Hanrahan 2001, equation 13, constants folded in).
vec3 environmentDiffuse(vec3 n)
{
    const vec3 d = toEnvironment(n);
    const vec4 c[9] = frame.environmentSh;
    const vec3 e = c[0].rgb + c[1].rgb * d.y + c[2].rgb * d.z + c[3].rgb * d.x + c[4].rgb * (d.x * d.y) +
                   c[5].rgb * (d.y * d.z) + c[6].rgb * (3.0 * d.z * d.z - 1.0) + c[7].rgb * (d.x * d.z) +
                   c[8].rgb * (d.x * d.x - d.y * d.y);
    return max(e, vec3(0.0));
}

// The share of the prefiltered radiance the specular layer reflects, single and multiple scattering together, from
// the split-sum table's scale A and bias B (Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", JCGT 8(1)): the single-scattering Fresnel grows towards grazing angles only as far
// as the roughness lets it (Fr), and the energy single scattering loses, 1 - (A + B), comes back in proportion to the
// average Fresnel F_avg. As the Khronos glTF Sample Viewer does (getIBLGGXFresnel), the multiple-scattering term is
// lit by the prefiltered radiance too, where the paper lights it by the irradiance.
vec3 environmentReflectance(vec3 f0, vec2 ab, float nv, float roughness)
{
    const vec3 fr = max(vec3(1.0 - roughness), f0) - f0;
    const vec3 kS = f0 + fr * pow(1.0 - nv, 5.0);
    const vec3 fssEss = kS * ab.x + ab.y;
    const float ems = 1.0 - (ab.x + ab.y);
    const vec3 fAverage = f0 + (1.0 - f0) / 21.0;
    const vec3 fmsEms = ems * fssEss * fAverage / (1.0 - fAverage * ems);
    return fssEss + fmsEms;
}

// The environment's light leaving the surface towards v, with the same metallic-roughness split as brdf(): the
// specular layer reflects environmentReflectance, the dielectric's diffuse takes what it does not. Ambient occlusion
// darkens the diffuse; the specular takes Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", section 4.10.2,
// equation 62 (with their roughness, the GGX alpha).
vec3 environmentLight(vec3 n, vec3 v, vec3 base, float metallic, float roughness, float occlusion)
{
    const float nv = max(dot(n, v), 1e-4);
    const vec3 f0 = mix(vec3(0.04), base, metallic);
    const vec2 ab = textureLod(environmentBrdf, vec2(nv, roughness), 0.0).rg;
    const vec3 reflectance = environmentReflectance(f0, ab, nv, roughness);
    const vec3 r = toEnvironment(reflect(-v, n));
    const vec3 prefiltered = textureLod(environmentSpecular, equirectUv(r), roughness * frame.environmentLastLevel).rgb;
    const float alpha = roughness * roughness;
    const float specularOcclusion = clamp(pow(nv + occlusion, exp2(-16.0 * alpha - 1.0)) - 1.0 + occlusion, 0.0, 1.0);
    const vec3 diffuse = (1.0 - metallic) * base * (1.0 - reflectance) * environmentDiffuse(n);
    return frame.environmentIntensity * (diffuse * occlusion + prefiltered * reflectance * specularOcclusion);
}
