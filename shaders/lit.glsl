// The lit pass's blocks (penumbra::render::LitFrameUniforms, LitObjectUniforms, generated into lit_blocks.glsl) and
// material maps.

#include "lit_constants.glsl"

#include "lit_blocks.glsl"

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

