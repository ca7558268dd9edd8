#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Scene.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::apps {

// One shadow atlas as read back, by the name files and reports use: "directional" (the cascades
// of the directional lights), "other" (spot and point lights) and, in cube-map mode, "cube" (the
// first point light's six cube faces side by side, +X to -Z).
struct AtlasPictures {
    std::string name;
    rhi::Image picture;    // render::atlasPicture of depth, in linear light depth
    rhi::DepthImage depth; // raw window depth as read back
    // render::lightDepthFraction of the window depth, comparable across conventions: orthographic
    // window depth is linear, perspective window depth the same function of view depth in every
    // depth range (reversed: 1 minus it), so rounding stays uniform where linear depth would
    // magnify it towards the far plane.
    std::vector<float> lightDepth;
};

// A scene rendered through one configuration and read back.
struct ShadowPictures {
    std::string configuration;
    rhi::DepthRange depthRange = rhi::DepthRange::ZeroToOne; // the device's conventions
    bool reversedZ = false;
    rhi::Image lit;
    rhi::Image cascades; // empty unless the frame asked for the cascade view
    std::vector<AtlasPictures> atlases;
    render::FrameStats stats;
    std::vector<std::string> notes;

    // Throws rhi::Error naming the atlases there are.
    const AtlasPictures& atlas(std::string_view name) const;
};

// The scenes the tool renders by name: "test" (scene::makeShadowTestScene, four lights), "key-light"
// (scene::makeSingleLightScene), "mixed" (scene::makeMixedLightsScene: key, spot and point lights) and
// "room" (scene::makePointLightRoomScene) and "forest" (scene::makeForestScene). Unknown names throw rhi::Error
// listing these.
scene::Scene namedScene(const std::string& name);
bool isNamedScene(std::string_view name);
inline constexpr const char* kSceneNames = "test, key-light, mixed, room, forest, contact";

// Renders scene.camera's view; the cascade view too when frame.cascadeView is set. Throws
// rhi::Error when the device reports a validation or debug message.
ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame);

// The file stem of an atlas in a demo folder: "atlas" for "directional", "<name>-atlas" otherwise.
std::string atlasFileStem(std::string_view name);

// The demo folder: lit.png, cascades.png (when rendered), and <atlasFileStem>.png and .exr per atlas.
void writeShadowPictures(const std::filesystem::path& folder, const ShadowPictures& pictures);

} // namespace penumbra::apps
