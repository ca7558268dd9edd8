#pragma once

#include "AnimationPlayer.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <optional>
#include <tuple>
#include <string>
#include <vector>

namespace penumbra::viewer {

// One object's shadow choices as the panel edits them (scene::Object::castShadows, receiveShadows, mobility).
struct ObjectShadowState {
    scene::ShadowCasting cast = scene::ShadowCasting::On;
    bool receive = true;
    scene::Mobility mobility = scene::Mobility::Static;
};

// What the panel edits. The viewer renders with the last state that passed validation, so an
// invalid edit shows its error in the panel and changes nothing else.
struct ViewState {
    shadows::ShadowSettings shadows;
    std::vector<scene::DirectionalLight> lights;
    std::vector<scene::SpotLight> spotLights;
    std::vector<scene::PointLight> pointLights;
    std::vector<ObjectShadowState> objects; // one per scene object, in scene order
    bool cascadeView = false;
    bool atlasOverlay = false;
    float maxAnisotropy = 8.0f; // render::FrameDesc::maxAnisotropy
    std::uint32_t msaa = 1; // render::FrameDesc::msaa
    render::ShadowPath shadowPath = render::ShadowPath::Forward; // render::FrameDesc::shadowPath
    float environmentIntensity = 1.0f; // render::EnvironmentLight::intensity
    float environmentRotation = 0.0f; // render::EnvironmentLight::rotationDegrees
    bool hasEnvironment = false; // the view has an environment image: the panel shows its sliders
    bool redrawStaticMaps = false; // once: SceneRenderer::requestStaticShadowUpdate (the on-demand mode's button)
};

// What the panel shows besides the state.
struct PanelStatus {
    std::string error; // why the edited state is not applied; empty when it is
    double frameMs = 0.0; // wall time of the last frame
    render::FrameStats stats; // the last frame's passes
    std::vector<std::string> notes; // SceneRenderer::notes()
    const rhi::Texture* atlasPicture = nullptr; // shown when atlasOverlay is on
    std::uint32_t msaaCounts = 1; // the sample counts the device offers the lit pass (rhi::Capabilities::sampleCounts)
};

// Makes `edited` the state in use if it is valid: its shadow settings pass shadows::validate and
// its lights (directions normalised, as the panel edits them freely) pass scene.validate(); then
// `applied` and the scene's lights take it and the result is empty. Otherwise nothing changes and the
// result is the error, naming the field.
std::string applyViewState(const ViewState& edited, ViewState& applied, scene::Scene& scene);

// The state's lights as the scene holds them, for starting a view.
ViewState viewStateOf(const scene::Scene& scene);

// Draws the panel into the current ImGui frame; returns whether the user changed `state`.
// Object names come from `scene`.
bool drawSettingsPanel(ViewState& state, const PanelStatus& status, const scene::Scene& scene);

// Draws the animation window where the scene has animations: the animations listed by index and name, play / pause
// and a time slider (AnimationPlayer).
void drawAnimationPanel(AnimationPlayer& player, const scene::Rig& rig);

} // namespace penumbra::viewer
