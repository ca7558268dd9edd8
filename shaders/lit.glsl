// Uniform blocks of the lit pass (penumbra::render::LitFrameUniforms, LitObjectUniforms).

#include "lit_constants.glsl"

layout(std140, binding = PENUMBRA_BINDING_FRAME) uniform Frame {
    mat4 viewProjection;
    vec4 cameraPosition; // xyz
    vec4 cameraForward;  // xyz, unit: view depth is the distance along it
    vec4 lightColor[PENUMBRA_MAX_LIT_DIRECTIONAL_LIGHTS];     // linear rgb x intensity
    vec4 lightDirection[PENUMBRA_MAX_LIT_DIRECTIONAL_LIGHTS]; // xyz from the light into the scene, w = shadow slot or -1
    vec4 ambient;        // linear rgb
    int directionalLightCount;
    int litView;         // penumbra::render::LitView (PENUMBRA_VIEW_*)
    int localLightCount;
    int visibilityLight; // the visibility view's light (directional lights first, then spot and point lights)
    vec4 cameraRight;    // xyz the view's x axis, w = tan of the half field of view along it (local_lights.glsl)
    vec4 cameraUp;       // xyz the view's y axis, w = tan of the half field of view along it
    vec4 clusterSlices;  // near plane, far plane, slice scale, slice bias (penumbra::shadows::LightClusterUniforms)
    vec4 ambientGround;  // linear rgb from below (= ambient without a hemisphere)
} frame;

// What the instances of one draw share (their transforms are per instance, instance.glsl).
layout(std140, binding = PENUMBRA_BINDING_OBJECT) uniform Object {
    vec4 baseColor;          // linear rgb, alpha
    vec4 surface;            // metallic, roughness, alpha cutoff, caster mode (material.glsl)
    int receivesShadows;
    int materialMaps;        // textures present, bit per PENUMBRA_TEXTURE_*
    int unlit;
    int blended;
    vec4 emissive;           // linear rgb, w = occlusion strength
    vec4 normal;             // normal texture scale
    vec4 uvTransforms[2 * PENUMBRA_TEXTURE_SLOTS]; // per PENUMBRA_TEXTURE_*: its uv transform rows (material.glsl, transformedUv)
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
bool hasMap(int slot) { return ((PENUMBRA_LIT_MAPS >> slot) & 1) != 0 && (object.materialMaps & (1 << slot)) != 0; }

vec4[2] uvRows(int slot) { return vec4[2](object.uvTransforms[2 * slot], object.uvTransforms[2 * slot + 1]); }

