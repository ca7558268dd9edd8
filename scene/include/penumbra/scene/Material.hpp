#pragma once

#include "penumbra/scene/TextureImage.hpp"

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace penumbra::scene {

// How a material's surface enters the shadow maps: the shadow modes of Catlike Coding's "Directional Shadows"
// tutorial, section "Transparency".
enum class CasterMode : std::uint8_t {
    On, // solid caster
    Clip, // alpha-tested: texels with materialAlpha < alphaCutoff cast nothing
    Dither, // alpha as coverage: a caster texel survives where alpha >= a screen-space dither value
    Off, // casts no shadow (still drawn and still receives)
};

// KHR_texture_transform: uv' = translation(offset) * rotation(rotation) * scale(scale) * uv, applied to
// the texture coordinate set `texCoord` (0 = TEXCOORD_0, 1 = TEXCOORD_1; glTF 2.0, textureInfo.texCoord).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f; // radians, counter-clockwise in uv space as the extension defines it
    glm::vec2 scale{1.0f};

    // The 3 x 3 matrix of the extension's definition (its columns 0 and 1 and the translation column).
    glm::mat3 matrix() const;
};

inline constexpr std::uint32_t kTexCoordSets = 2; // TEXCOORD_0 and TEXCOORD_1

// One texture of a material: an image of Scene::textures, read through a uv set and a transform.
struct MaterialTexture {
    std::uint32_t image = 0;
    std::uint32_t texCoord = 0; // below kTexCoordSets
    TextureTransform transform;
};

// The textures a material may have, in the order the lit pass binds them (render::LitObjectUniforms,
// shaders/lit.glsl): one fact, numbered once here.
enum class TextureSlot : std::uint32_t { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive };
inline constexpr std::uint32_t kTextureSlots = 5;

// A glTF 2.0 metallic-roughness material: factors, textures, alpha mode, sidedness.
struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f}; // linear RGB; a is the alpha of Clip and Dither casters
    float metallic = 0.0f;
    float roughness = 0.5f;
    float alphaCutoff = 0.5f; // Clip only
    CasterMode caster = CasterMode::On;
    bool receiveShadows = true;
    // glTF 2.0 material.doubleSided: no back-face culling in any pass, the back face lit with the
    // flipped normal. Single-sided materials are culled.
    bool doubleSided = false;
    // KHR_materials_unlit: the surface shows its base colour (times vertex colour) without lighting;
    // it still casts shadows.
    bool unlit = false;
    // glTF alphaMode BLEND: drawn alpha-blended after the opaque surfaces, back to front.
    bool blend = false;
    // Linear RGB added after lighting: emissiveFactor x KHR_materials_emissive_strength.
    glm::vec3 emissive{0.0f};
    float normalScale = 1.0f; // normalTexture.scale
    float occlusionStrength = 1.0f; // occlusionTexture.strength, in [0, 1]

    // Images of Scene::textures, indexed by TextureSlot:
    // - BaseColor: sRGB-encoded RGBA, multiplied with baseColor in every pass; its alpha then replaces
    //   the Clip checker below.
    // - MetallicRoughness: B = metallic, G = roughness, multiplying the factors (glTF 2.0 section 3.9.2).
    // - Normal: tangent-space normal, scaled in x and y by normalScale (section 3.9.3).
    // - Occlusion: R, scales the ambient term by 1 + strength * (R - 1) (section 3.9.3).
    // - Emissive: sRGB-encoded RGB, multiplying emissive.
    std::array<std::optional<MaterialTexture>, kTextureSlots> textures{};

    // The texture in `slot`, if any.
    std::optional<MaterialTexture>& texture(TextureSlot slot) { return textures[std::size_t(slot)]; }
    // The texture in `slot`, if any.
    const std::optional<MaterialTexture>& texture(TextureSlot slot) const { return textures[std::size_t(slot)]; }
};

// The coordinate at which `texture` is read from a point with uv sets uv0 and uv1: its set, transformed
// (uv0 itself without a texture), as material.glsl's transformedUv does.
glm::vec2 textureUv(const std::optional<MaterialTexture>& texture, glm::vec2 uv0, glm::vec2 uv1);

// Cells per uv unit of the procedural checker that gives Clip materials their holes.
// Odd, so the pattern is symmetric under u -> 1 - u and v -> 1 - v: opposite faces of a box
// run their uv in mirrored directions, and only then do a thin clipped box's holes line up
// through both faces (with an even count every hole on top would be covered underneath).
inline constexpr float kClipCheckerCells = 5.0f;

// The alpha every pass sees for `material` at texture coordinate `uv`.
// - Clip materials: baseColor.a on the checker's even cells, 0 on its odd cells
//   (cell = floor(uv * kClipCheckerCells)), so clipped casters have holes in a pattern a test
//   can predict. The lit pass clips the surface with the same alpha and cutoff, so the holes
//   are visible from the camera too; shaders must implement this exact function.
// - Every other mode: baseColor.a.
// - Textured materials (`baseColor` is the image of the material's base colour texture, `uv` textureUv's): baseColor.a
//   times the texture's alpha
//   (textureAlpha) instead of the checker, in every mode, as the shaders do.
float materialAlpha(const Material& material, glm::vec2 uv, const TextureImage* baseColor = nullptr);

// The texture's alpha at `uv`: bilinear between texel centres on its full-size level, repeating, as the
// passes' repeat sampler gives it where no smaller mip level is selected.
float textureAlpha(const TextureImage& texture, glm::vec2 uv);

} // namespace penumbra::scene
