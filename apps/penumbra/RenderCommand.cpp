#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "Interrupt.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "penumbra/rhi/AtomicFile.hpp"
#include "SceneOptions.hpp"
#include "ToolDevices.hpp"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <optional>

namespace penumbra::apps {
namespace {

struct RenderOptions {
    std::vector<std::string> backends = {"vulkan"};
    SceneOptions scene;
    std::string out = "out/render/lit.png";
    std::string atlas; // file prefix; empty: no atlas files
    std::vector<std::string> debug;
    std::string graph; // .dot file; empty: none
    bool validate = false;
};

// X.png -> X-<suffix>.png
std::filesystem::path withSuffix(const std::filesystem::path& path, const std::string& suffix)
{
    return path.parent_path() / (path.stem().string() + "-" + suffix + path.extension().string());
}

void writeOutputs(const RenderOptions& options, const ShadowPictures& pictures, bool several)
{
    const std::filesystem::path lit =
        several ? withSuffix(options.out, pictures.configuration) : std::filesystem::path(options.out);
    std::vector<std::string> written = {lit.string()};
    parity::writePicture(lit, pictures.lit);
    if (!pictures.cascades.bytes.empty()) {
        written.push_back(withSuffix(lit, "cascades").string());
        parity::writePicture(written.back(), pictures.cascades);
    }
    if (!options.atlas.empty()) {
        const std::string prefix =
            several ? fmt::format("{}-{}", options.atlas, pictures.configuration) : options.atlas;
        for (const AtlasPictures& atlas : pictures.atlases) {
            const std::string stem = fmt::format("{}-{}", prefix, atlas.name);
            parity::writeExr(stem + ".exr", atlas.depth);
            parity::writePng(stem + ".png", atlas.picture);
            written.insert(written.end(), {stem + ".exr", stem + ".png"});
        }
    }
    if (!options.graph.empty()) {
        written.push_back(several ? withSuffix(options.graph, pictures.configuration).string() : options.graph);
        rhi::writeFileAtomically(written.back(), pictures.frameGraph);
    }
    for (const std::string& file : written)
        fmt::print("  wrote {}\n", file);
}

void render(const RenderOptions& options)
{
    const std::vector<std::string> configurations = expandBackends(options.backends);
    // Everything that can be refused is checked before the first device starts.
    const LoadedScene loaded = loadScene(options.scene);
    render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    frame.cascadeView = !options.debug.empty();
    const std::optional<shadows::StaticShadowBake> bake = loadBake(options.scene);
    for (const std::string& note : loaded.notes)
        fmt::print("{}: {}\n", options.scene.scene, note);

    // Rendered first, written after: a failing configuration leaves no files from the others.
    std::vector<ShadowPictures> all;
    std::optional<truth::CpuGBuffer> gbuffer;
    for (const std::string& configuration : configurations) {
        stopIfInterrupted();
        const auto start = std::chrono::steady_clock::now();
        all.push_back(renderShadowScene(
            configuration, loaded.scene, frame,
            {.validate = options.validate, .readAtlases = !options.atlas.empty(), .bake = bake ? &*bake : nullptr}));
        if (!loaded.scene.lights.empty()) {
            if (!gbuffer)
                gbuffer = texelDensityGBuffer(loaded.scene, frame);
            all.back().texelsOnScreen = texelsOnScreen(all.back(), loaded.scene, *gbuffer);
        }
        printStats(all.back(), loaded.scene);
        // The first frame's cost as a user waits for it: what the pipeline cache saves shows here.
        const std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
        fmt::print("  first frame with device, pipelines and read-back: {:.0f} ms\n", wall.count());
    }
    if (const std::shared_ptr<rhi::PipelineCache>& cache = toolPipelineCache())
        fmt::print("{}\n", cache->summary());
    stopIfInterrupted();
    for (const ShadowPictures& pictures : all)
        writeOutputs(options, pictures, all.size() > 1);
}

} // namespace

void addRenderCommand(CLI::App& app)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a scene (built-in or glTF) through one or more configurations into a picture, and optionally "
                  "its shadow atlases and cascade view; prints each pass's GPU time");
    command
        ->add_option("-b,--backend", options->backends,
                     "vulkan, opengl, any configuration name (vulkan-reversed, opengl-noclip, ...) or all (every "
                     "configuration); several, comma-separated, give one output per configuration, named "
                     "X-<configuration>.png")
        ->check(backendValidator())
        ->delimiter(',')
        ->capture_default_str();
    addSceneOptions(*command, options->scene);
    command->add_option("-o,--out", options->out, "Lit picture: .png, or .exr (linear float RGBA)")
        ->check(CLI::Validator(
            [](std::string& path) {
                return parity::isPicturePath(path) ? std::string()
                                                   : fmt::format("'{}' does not end in .png or .exr", path);
            },
            "FILE"))
        ->capture_default_str();
    command->add_option("--atlas", options->atlas,
                        "Write each shadow atlas to PREFIX-<atlas>.exr (raw depth, one 32-bit float channel, as read "
                        "back) and PREFIX-<atlas>.png; atlases: directional. With several configurations "
                        "PREFIX-<configuration>-<atlas>");
    command->add_option("--debug", options->debug, "cascades: also write X-cascades.png, tinted by cascade")
        ->check(CLI::IsMember({"cascades"}));
    command->add_option("--graph", options->graph,
                        "Write the frame's graph as Graphviz dot to FILE (passes in running order, the textures each "
                        "reads and writes, culled passes and passes off this frame marked); with several "
                        "configurations FILE-<configuration>.dot");
    addValidateFlag(*command, options->validate);
    command->callback([options] {
        installInterruptHandler();
        render(*options);
    });
}

} // namespace penumbra::apps
