// Uniform blocks of the lit pass (penumbra::render::LitFrameUniforms, LitObjectUniforms).

#include "lit_constants.glsl"

layout(std140, binding = 0) uniform Frame {
    mat4 viewProjection;
    vec4 cameraPosition;     // xyz
    vec4 cameraForward;      // xyz, unit: view depth is the distance along it
    vec4 lightColor[8];      // linear rgb x intensity
    vec4 lightDirection[8];  // xyz from the light into the scene, w = shadow slot or -1
    vec4 ambient;            // linear rgb
    ivec4 config;            // directional light count, view (penumbra::render::LitView), local light count, the
                             // visibility view's light (directional lights first, then spot and point lights)
    vec4 localPosition[16];  // xyz, w = 1 / range^2
    vec4 localColor[16];     // linear rgb x intensity, w = 1 for a point light, 0 for a spot light
    vec4 localAxis[16];      // spot cone axis (unit, away from the light)
    vec4 localShadow[16];    // spot angle scale and offset, first shadow tile or -1, shadow strength
    vec4 ambientGround;      // linear rgb from below (= ambient without a hemisphere)
} frame;

layout(std140, binding = 1) uniform Object {
    mat4 model;
    mat4 normalMatrix;       // inverse transpose of the model matrix
    vec4 baseColor;          // linear rgb, alpha
    vec4 surface;            // metallic, roughness, alpha cutoff, caster mode (material.glsl)
    ivec4 flags;             // receives shadows, textures present (bit per PENUMBRA_TEXTURE_*), unlit, blended
    vec4 emissive;           // linear rgb, w = occlusion strength
    vec4 normal;             // normal texture scale, sign of det(model)
    vec4 uvTransforms[10];   // per PENUMBRA_TEXTURE_*: its uv transform rows (material.glsl, transformedUv)
} object;

// A white texel where the material has no such texture.
layout(binding = PENUMBRA_BINDING_BASE_COLOR_MAP) uniform sampler2D baseColorMap; // sRGB-encoded
layout(binding = PENUMBRA_BINDING_METALLIC_ROUGHNESS_MAP) uniform sampler2D metallicRoughnessMap; // B metal, G rough
layout(binding = PENUMBRA_BINDING_NORMAL_MAP) uniform sampler2D normalMap;       // tangent space, 0.5 = 0
layout(binding = PENUMBRA_BINDING_OCCLUSION_MAP) uniform sampler2D occlusionMap; // R
layout(binding = PENUMBRA_BINDING_EMISSIVE_MAP) uniform sampler2D emissiveMap;   // sRGB-encoded
// The base colour map without anisotropic filtering: the alpha that every pass decides coverage by
// (render::GpuScene::coverageSampler).
layout(binding = PENUMBRA_BINDING_COVERAGE_MAP) uniform sampler2D coverageMap;

// Only the maps the shader is built with (PENUMBRA_LIT_MAPS): the others are left out of it.
bool hasMap(int slot) { return ((PENUMBRA_LIT_MAPS >> slot) & 1) != 0 && (object.flags.y & (1 << slot)) != 0; }

vec4[2] uvRows(int slot) { return vec4[2](object.uvTransforms[2 * slot], object.uvTransforms[2 * slot + 1]); }

