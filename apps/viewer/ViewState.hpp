#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace penumbra::viewer {

// What the panel edits. The viewer renders with the last state that passed validation, so an
// invalid edit shows its error in the panel and changes nothing else.
struct ViewState {
    shadows::ShadowSettings shadows;
    std::vector<scene::DirectionalLight> lights;
    bool cascadeView = false;
    bool atlasOverlay = false;
};

// What the panel shows besides the state.
struct PanelStatus {
    std::string error;               // why the edited state is not applied; empty when it is
    double frameMs = 0.0;            // wall time of the last frame
    render::FrameStats stats;        // the last frame's passes
    std::vector<std::string> notes;  // SceneRenderer::notes()
    const rhi::Texture* atlasPicture = nullptr; // shown when atlasOverlay is on
};

// Draws the panel into the current ImGui frame; returns whether the user changed `state`.
bool drawSettingsPanel(ViewState& state, const PanelStatus& status);

} // namespace penumbra::viewer
