#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::apps {

// The shadow test scene rendered through one configuration and read back.
struct ShadowPictures {
    std::string configuration;
    rhi::DepthRange depthRange = rhi::DepthRange::ZeroToOne; // the device's conventions
    bool reversedZ = false;
    rhi::Image lit;
    rhi::Image cascades;
    rhi::Image atlas;          // render::atlasPicture of atlasDepth
    rhi::DepthImage atlasDepth; // raw window depth as read back
    std::vector<float> atlasLightDepth; // render::lightDepthFraction: comparable across conventions
    rhi::Image otherAtlas;               // the spot and point shadow atlas in linear light depth
    rhi::DepthImage otherAtlasDepth;
    // Window depth as a fraction from the far (0) to the near (1) plane: perspective window depth is the
    // same function of view depth in every depth range (reversed: 1 minus it), so this compares across
    // conventions with uniform rounding, where linear depth would magnify it towards the far plane.
    std::vector<float> otherAtlasNearness;
    // Cube-map mode: the first point light's six faces side by side (+X to -Z), as read back; empty otherwise.
    rhi::DepthImage cubeFacesDepth;
    std::vector<float> cubeFacesNearness;
    render::FrameStats stats;
    std::vector<std::string> notes;
};

// The scenes the tool renders by name: "test" (scene::makeShadowTestScene, four lights), "key-light"
// (scene::makeSingleLightScene), "mixed" (scene::makeMixedLightsScene) and "room"
// (scene::makePointLightRoomScene). Unknown names throw rhi::Error listing these.
scene::Scene namedScene(const std::string& name);

// Throws rhi::Error when the device reports a validation or debug message.
ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame);

// lit.png, atlas.png, atlas.exr, cascades.png, other-atlas.png and other-atlas.exr in `folder`.
void writeShadowPictures(const std::filesystem::path& folder, const ShadowPictures& pictures);

} // namespace penumbra::apps
