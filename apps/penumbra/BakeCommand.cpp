#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "SceneOptions.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <memory>

namespace penumbra::apps {
namespace {

struct BakeOptions {
    std::string backend = "vulkan";
    SceneOptions scene;
    std::string out;
    bool validate = false;
};

void bake(const BakeOptions& options)
{
    const std::vector<std::string> configurations = expandBackends({options.backend});
    if (configurations.size() != 1)
        throw rhi::Error(
            fmt::format("--backend '{}': a bake is made on one configuration (any one loads it)", options.backend));
    const LoadedScene loaded = loadScene(options.scene);
    render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    // A bake is the static maps: drawn once, whatever mode the settings keep them in at run time.
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
    auto device = createDevice(toolDeviceDesc(configurations[0], options.validate));
    render::SceneRenderer renderer(*device, loaded.scene);
    std::fprintf(stderr, "baking %s on %s...\n", options.scene.scene.c_str(), configurations[0].c_str());
    const render::FrameStats stats = renderer.render(loaded.scene.camera, frame);
    for (const std::string& update : stats.staticMapUpdates)
        fmt::print("  {}\n", update);
    for (const std::string& note : stats.notes)
        fmt::print("  note: {}\n", note);
    const shadows::StaticShadowBake bake = renderer.bakeStaticShadows(configurations[0]);
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", configurations[0], messages.size(), messages[0]));
    if (bake.maps.empty())
        throw rhi::Error(
            fmt::format("{}: nothing to bake: no light casts shadows on a static caster", options.scene.scene));
    shadows::writeStaticShadowBake(options.out, bake);
    fmt::print("baked {} light(s), {} static objects, {} caster draws, into {}/manifest.json\n", bake.maps.size(),
               bake.objects.size(), stats.staticCasterDraws, options.out);
}

} // namespace

void addBakeCommand(CLI::App& app)
{
    auto options = std::make_shared<BakeOptions>();
    CLI::App* command = app.add_subcommand(
        "bake", "Render every light's static shadow map (the static casters' depth) and write it to a folder: "
                "manifest.json and one EXR of light-space depth per light, which render, bench and truth load with "
                "--baked on any configuration");
    command->add_option("-b,--backend", options->backend, "The configuration that bakes (one)")
        ->check(backendValidator())
        ->capture_default_str();
    addSceneOptions(*command, options->scene);
    command->add_option("-o,--out", options->out, "Folder of the bake (created)")->required();
    addValidateFlag(*command, options->validate);
    command->callback([options] { bake(*options); });
}

} // namespace penumbra::apps
