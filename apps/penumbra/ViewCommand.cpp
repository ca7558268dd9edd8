#include "ViewCommand.hpp"

#include "BackendOptions.hpp"
#include "EnvironmentOption.hpp"
#include "Commands.hpp"
#include "RenderSettings.hpp"
#include "SceneOptions.hpp"
#include "SettingsFieldOptions.hpp"
#include "ShadowScene.hpp"
#include "Viewer.hpp"

#include "penumbra/shadows/ShadowSettings.hpp"

#include <charconv>
#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace penumbra::apps {
namespace {

// "1280x720" -> width and height; an error message for CLI11 otherwise.
std::string parseWindowSize(const std::string& text, viewer::ViewerOptions& options)
{
    const std::size_t x = text.find('x');
    const auto number = [](std::string_view digits, std::uint32_t& value) {
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        return error == std::errc() && end == digits.data() + digits.size() && value >= 1 && value <= 8192;
    };
    if (x == std::string::npos || !number(std::string_view(text).substr(0, x), options.width) ||
        !number(std::string_view(text).substr(x + 1), options.height))
        return fmt::format("'{}' is not WIDTHxHEIGHT with each between 1 and 8192", text);
    return {};
}

} // namespace

void addViewCommand(CLI::App& app)
{
    auto options = std::make_shared<viewer::ViewerOptions>();
    CLI::App* view = app.add_subcommand(
        "view",
        "Open a window on a scene: orbit (left drag), fly (right drag, W A S D Q E; + and - change the speed), zoom "
        "(scroll), F frames the scene, R resets the camera, Tab hides the settings panel");
    view->add_option("-b,--backend", options->configuration,
                     "vulkan or opengl, or any configuration name (vulkan-reversed, opengl-noclip, ...)")
        ->check(configurationValidator());
    view->add_option("--scene", options->scene,
                     fmt::format("A built-in scene ({}) or a .gltf or .glb file", kSceneNames));
    view->add_option_function<std::string>(
        "--size",
        [options](const std::string& text) {
            if (const std::string error = parseWindowSize(text, *options); !error.empty())
                throw CLI::ValidationError("--size", error);
        },
        "Window size WIDTHxHEIGHT in pixels (default 1280x720)");
    CLI::Option* frames = view->add_option("--frames", options->frames, "Render this many frames, then exit")
                              ->check(CLI::Range(1u, 1000000u));
    view->add_option("--screenshot", options->screenshot, "PNG of the window's last frame, read back from the window")
        ->needs(frames);
    view->add_flag("!--no-ui", options->ui, "Hide the settings panel");
    view->add_flag("--cascade-view", options->cascadeView, "Start with the cascade view");
    view->add_flag("--atlas-overlay", options->atlasOverlay, "Start with the shadow atlas overlay");
    addValidateFlag(*view, options->validate);
    view->add_option("--filter", options->filter,
                     fmt::format("Every light's shadow filter: {}", shadows::filterCommandNames()))
        ->check(filterValidator());
    addSettingsFieldOptions(*view, options->settingsFields);
    view->add_option("--light-size", options->lightSize,
                     "Every light's source size: degrees of angular diameter (directional), world units of radius "
                     "(spot, point)")
        ->check(CLI::NonNegativeNumber);
    view->add_option(
            "--baked", options->baked,
            "Static shadow maps from this `penumbra bake` folder; the viewer stops with the bake's message when "
            "the scene, a light or the static settings no longer match it")
        ->check(CLI::ExistingDirectory);
    view->callback([options] {
        // The render-level fields set the viewer's options; the shadow settings' go on to the viewer, which sets
        // them over the settings it fits to the scene.
        RenderSettings render;
        SettingsFieldValues shadowFields;
        for (const auto& [path, text] : options->settingsFields)
            if (isRenderLevelField(path))
                renderSettingsTable().set(render, path, text);
            else
                shadowFields.emplace(path, text);
        options->settingsFields = std::move(shadowFields);
        options->maxAnisotropy = render.anisotropy;
        options->msaa = render.msaa;
        options->shadowPath = render.shadowPath;
        const std::string extension = std::filesystem::path(options->scene).extension().string();
        options->environment =
            environmentOf(render.environment.source, extension == ".gltf" || extension == ".glb",
                          render.environment.intensity, render.environment.rotation, "--environment");
        viewer::runViewer(*options);
    });
}

} // namespace penumbra::apps
