#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/Scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>

namespace penumbra::apps {

// What a user of the viewer changes between frames, one at a time.
enum class SoakChange : std::uint8_t {
    DirectionalAtlasSize,
    LocalAtlasSize,
    DirectionalAtlasFormat,
    LocalAtlasFormat,
    DirectionalFilter,
    LocalFilter,
    LightFilter,
    CascadeCount,
    CascadeBlend,
    PointMode,
    CubeMapSize,
    SoftSamples,
    Anisotropy,
    DepthPrepass,
    AddPointLight,
    AddSpotLight,
    MoveLight,
    RemoveLight,
    Resize,
    SceneReload, // last: drawn less often than the others
};
inline constexpr std::size_t kSoakChangeCount = 20;

std::string_view soakChangeName(SoakChange change);

// One change: a scene reload one time in 50, the others uniformly.
SoakChange drawSoakChange(std::mt19937& random);

// The scene and frame a soak edits, and what they started as (sizes are drawn up to the starting size).
struct SoakState {
    scene::Scene& scene;
    render::FrameDesc& frame;
    const render::FrameDesc& start;
    scene::Bounds bounds; // of the scene's objects: where added lights go
};

// Applies `change` (everything but SceneReload, which rebuilds the renderer and is the caller's) with values
// drawn from `random`, always valid ones: the settings' ranges (shadows::validate) and at most
// kMaxSoakLocalLights spot and point lights.
inline constexpr std::size_t kMaxSoakLocalLights = 16; // a soak's frames stay quick on a software renderer
void applySoakChange(SoakChange change, std::mt19937& random, SoakState& state);

} // namespace penumbra::apps
