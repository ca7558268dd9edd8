#pragma once

#include "penumbra/scene/TextureImage.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace penumbra::scene {

// How a material's surface enters the shadow maps (the seeds' _Shadows keyword enum).
enum class CasterMode : std::uint8_t {
    On,     // solid caster
    Clip,   // alpha-tested: texels with materialAlpha < alphaCutoff cast nothing
    Dither, // alpha as coverage: a caster texel survives where alpha >= a screen-space dither value
    Off,    // casts no shadow (still drawn and still receives)
};

struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f}; // linear RGB; a is the alpha of Clip and Dither casters
    float metallic = 0.0f;
    float roughness = 0.5f;
    float alphaCutoff = 0.5f; // Clip only
    CasterMode caster = CasterMode::On;
    bool receiveShadows = true;
    // Index into Scene::textures (sRGB-encoded RGBA8), multiplied with baseColor in every pass
    // (glTF's baseColorTexture): its alpha then replaces the Clip checker below.
    std::optional<std::uint32_t> baseColorTexture;
};

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
// - Textured materials (`baseColor` is the material's baseColorTexture): baseColor.a times the texture's alpha
//   (textureAlpha) instead of the checker, in every mode, as the shaders do.
float materialAlpha(const Material& material, glm::vec2 uv, const TextureImage* baseColor = nullptr);

// The texture's alpha at `uv`: bilinear between texel centres on its full-size level, repeating, as the
// passes' repeat sampler gives it where no smaller mip level is selected.
float textureAlpha(const TextureImage& texture, glm::vec2 uv);

} // namespace penumbra::scene
