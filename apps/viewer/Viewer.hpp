#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace penumbra::viewer {

struct ViewerOptions {
    std::string configuration = "vulkan"; // a named configuration (penumbra::parseConfiguration)
    std::string scene = "test";
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    std::optional<std::uint32_t> frames; // render this many frames, then exit; else until closed
    std::string screenshot; // PNG of the window's last frame as read back from it, with `frames`
    bool ui = true; // the settings panel
    bool cascadeView = false; // start with the panel's toggles on
    bool atlasOverlay = false;
    float maxAnisotropy = 8.0f; // of texture sampling, 1 (off) to 16, as render::FrameDesc takes it
    std::uint32_t msaa = 1; // samples per pixel of the lit pass, as render::FrameDesc takes it
    render::ShadowPath shadowPath = render::ShadowPath::Forward; // as render::FrameDesc takes it
    bool validate = false; // the validation layer / debug output (penumbra view --validate)
    std::string filter; // every light's shadow filter (apps::applyLightOverrides); empty: their own
    std::optional<float> lightSize; // every light's source size
    // Shadow settings fields by path, from their options (penumbra view --projection close), over the defaults.
    std::map<std::string, std::string, std::less<>> settingsFields;
    // Image-based lighting (penumbra view --environment): the image, and the intensity and rotation the panel starts
    // from and edits.
    render::EnvironmentLight environment;
    std::string baked; // a `penumbra bake` folder: static maps from it (static.update onChange); empty: none
};

// Opens the window and runs the viewer. Throws rhi::Error when there is no display, no driver,
// or the device reported validation / debug messages (listed in the message).
void runViewer(const ViewerOptions& options);

} // namespace penumbra::viewer
