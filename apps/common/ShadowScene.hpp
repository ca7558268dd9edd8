#pragma once

#include "penumbra/parity/Picture.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"
#include "penumbra/truth/ShadowTruth.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::apps {

// One shadow atlas as read back, by the name files and reports use: "directional" (the cascades
// of the directional lights), "other" (the local lights' atlas: spot and point lights, under the name published
// before they were called local) and, in cube-map mode, "cube" (the first point light's six cube faces side by
// side, +X to -Z).
struct AtlasPictures {
    std::string name;
    rhi::Image picture; // render::atlasPicture of depth, in linear light depth
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
    std::string frameGraph; // the frame's graph as Graphviz dot (SceneRenderer::frameGraphDot)
    std::vector<std::string> notes;
    // truth::directionalTexelsPerMetre of the first directional light at kTexelDensityDepths (empty without one).
    std::vector<float> texelsPerMetre;
    shadows::DirectionalShadowPlan directionalPlan; // the directional plan the frame drew
    // texelsOnScreen's, where the caller asked for it (nullopt otherwise).
    std::optional<truth::OnScreenTexelDensity> texelsOnScreen;

    // Throws rhi::Error naming the atlases there are.
    const AtlasPictures& atlas(std::string_view name) const;
};

// View depths (metres) at which the tool reports the directional shadows' texels per metre: one or two in each
// cascade of the default splits (10, 25, 50, 100 m).
inline constexpr std::array<float, 5> kTexelDensityDepths{3.0f, 8.0f, 15.0f, 35.0f, 70.0f};
// The on-screen texel density's G-buffer takes one ray per this many pixels along each side.
inline constexpr std::uint32_t kTexelDensityStride = 8;

// The scenes the tool renders by name: "test" (scenes::makeShadowTestScene, four lights), "key-light"
// (scenes::makeSingleLightScene), "mixed" (scenes::makeMixedLightsScene: key, spot and point lights) and
// "room" (scenes::makePointLightRoomScene), "forest" (scenes::makeForestScene), "contact" (scenes::makeContactScene),
// "contact-local" (scenes::makeContactLocalLightsScene), "town" (scenes::makeTownScene), "cubes", "cubes-100k" and
// "cubes-1m" (scenes::makeCubeGridScene of 10 000, 100 000 and 1 000 000 cubes). Unknown names throw rhi::Error listing
// these.
scene::Scene namedScene(const std::string& name);
bool isNamedScene(std::string_view name);
inline constexpr const char* kSceneNames =
    "test, key-light, mixed, room, forest, contact, contact-local, town, street, cubes, cubes-100k, cubes-1m";

// How renderShadowScene runs: with the validation layer / debug output (the library's default, and the tests'),
// and whether it reads the atlases back (AtlasPictures; a 4096^2 atlas is 64 MiB to copy).
struct ShadowSceneRun {
    bool validate = true;
    bool readAtlases = true;
    const shadows::StaticShadowBake* bake = nullptr; // static maps from a bake (SceneRenderer::useBakedShadows)
};

// Renders scene.camera's view on `device`; the cascade view too when frame.cascadeView is set.
ShadowPictures renderShadowScene(rhi::Device& device, const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame, bool readAtlases = true,
                                 const shadows::StaticShadowBake* bake = nullptr);
// The same on a device of its own; throws rhi::Error when the device reports a validation or debug message.
ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame, const ShadowSceneRun& run = {});

// What the parity harness compares: "lit" (colour) and each atlas by its atlasFileStem ("atlas",
// "other-atlas", "cube-atlas"), depth compared in its light-depth fraction (AtlasPictures::lightDepth).
// The camera's view ray-cast at one sample per kTexelDensityStride x kTexelDensityStride pixels of the frame; the
// same in every configuration.
truth::CpuGBuffer texelDensityGBuffer(const scene::Scene& scene, const render::FrameDesc& frame);
// truth::directionalTexelsOnScreen of the first directional light of the pictures' plan over `gbuffer`.
truth::OnScreenTexelDensity texelsOnScreen(const ShadowPictures& pictures, const scene::Scene& scene,
                                           const truth::CpuGBuffer& gbuffer);

std::vector<parity::Picture> parityPictures(const ShadowPictures& pictures);

// The file stem of an atlas in a demo folder: "atlas" for "directional", "<name>-atlas" otherwise.
std::string atlasFileStem(std::string_view name);

} // namespace penumbra::apps
