// penumbra truth: a scene's shadow maps against a CPU ray cast of the same pixels, per shadowed light.
#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "Interrupt.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "SceneOptions.hpp"
#include "ToolDevices.hpp"
#include "TruthPictures.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/truth/ShadowTruth.hpp"
#include "penumbra/truth/SoftShadowTruth.hpp"
#include "penumbra/truth/AreaLightTruth.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/truth/RayCaster.hpp"

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>

namespace penumbra::apps {
namespace {

struct TruthOptions {
    std::string backend = "vulkan";
    SceneOptions scene;
    std::string out;
    bool validate = false;
};

// The lights the frame gives a shadow map and draws, in the lit pass's order.
std::vector<scene::LightRef> shadowedLights(const render::ShadowPlans& plans, const scene::Scene& scene)
{
    std::vector<scene::LightRef> lights;
    const std::size_t directional = std::min<std::size_t>(scene.lights.size(), render::maxLitDirectionalLights);
    for (std::uint32_t i = 0; i < directional; ++i)
        if (plans.directional.shadowSlots[i] >= 0)
            lights.push_back({scene::LightKind::Directional, i});
    for (std::uint32_t i = 0; i < scene.spotLights.size(); ++i)
        if (plans.local.spotTiles[i] >= 0)
            lights.push_back({scene::LightKind::Spot, i});
    for (std::uint32_t i = 0; i < scene.pointLights.size(); ++i)
        if (plans.local.pointShadows[i] >= 0)
            lights.push_back({scene::LightKind::Point, i});
    return lights;
}

// One line on stderr, redrawn as rows finish: "tracing <what> [#####-----]  50%".
truth::TraceProgress progressBar(std::string what)
{
    return [what = std::move(what), shown = -1](std::uint32_t done, std::uint32_t rows) mutable {
        stopIfInterrupted();
        const int percent = rows == 0 ? 100 : static_cast<int>(100u * done / rows) / 5 * 5;
        if (percent == shown)
            return;
        shown = percent;
        const int filled = percent / 5;
        fmt::print(stderr, "\rtracing {} [{}{}] {:3}%", what, std::string(std::size_t(filled), '#'),
                   std::string(std::size_t(20 - filled), '-'), percent);
        if (done == rows)
            fmt::print(stderr, "\n");
        std::fflush(stderr);
    };
}

std::string percent(double share) { return fmt::format("{:.3f}%", 100.0 * share); }

// The shadowed class by the caster nearest each receiver, so that a missing or misplaced caster can be found.
nlohmann::json casterReport(const scene::Scene& scene, const truth::TruthComparison& c)
{
    nlohmann::json casters = nlohmann::json::array();
    for (const auto& [object, figures] : c.shadowedBy)
        casters.push_back({{"name", scene.objects.at(object).name},
                           {"shadowedCompared", figures.compared},
                           {"shadowedAgreement", figures.share()}});
    return casters;
}

nlohmann::json lightReport(const scene::Scene& scene, const LightTruth& t)
{
    const truth::TruthComparison& c = t.comparison;
    return {{"name", t.name},
            {"kind", scene::lightKindName(t.light.kind)},
            {"index", t.light.index},
            {"compared", c.compared()},
            {"litCompared", c.lit.compared},
            {"shadowedCompared", c.shadowed.compared},
            {"agreement", c.agreement()},
            {"litAgreement", c.lit.share()},
            {"shadowedAgreement", c.shadowed.share()},
            {"acnePixels", c.acne()},
            {"leakPixels", c.leaks()},
            {"contactGapTexels", t.contactGapTexels},
            {"contactShadowedPixels", t.contactGaps.shadowed},
            {"contactGapPixels", t.contactGaps.gaps},
            {"litNearEdges", c.lit.nearEdges},
            {"shadowedNearEdges", c.shadowed.nearEdges},
            {"litUndecided", c.lit.undecided},
            {"shadowedUndecided", c.shadowed.undecided},
            {"ditheredCompared", c.dithered.compared},
            {"ditheredExpectedLit", c.dithered.expectedLit()},
            {"ditheredRenderedLit", c.dithered.renderedLit()},
            {"casters", casterReport(scene, c)}};
}

// The area-light ray cast of lights with a source size whose shadow map is soft (Poisson or PCSS), or of every light
// with one when --light-size sets it: sourceSize, penumbraPixels and softMeanAbsError.
bool wantsSoftTruth(const TruthOptions& options, const scene::Scene& scene, const render::ShadowPlans& plans,
                    const scene::LightRef& light)
{
    return truth::lightSourceSize(scene, light) > 0.0f &&
           (options.scene.lightSize || shadows::isSoftFilter(truth::plannedShadowFilter(plans, light)));
}

void truth(const TruthOptions& options)
{
    const LoadedScene loaded = loadScene(options.scene);
    const scene::Scene& scene = loaded.scene;
    render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    if (std::filesystem::exists(options.out) && !std::filesystem::is_directory(options.out))
        throw rhi::Error(fmt::format("--out: '{}' exists and is not a folder", options.out));
    for (const std::string& note : loaded.notes)
        fmt::print("{}: {}\n", options.scene.scene, note);

    std::optional<shadows::StaticShadowBake> bake = loadBake(options.scene);
    auto device = createDevice(toolDeviceDesc(options.backend, options.validate));
    render::SceneRenderer renderer(*device, scene);
    if (bake)
        renderer.useBakedShadows(std::move(*bake));
    const render::ShadowPlans plans = renderer.planShadows(scene.camera, frame);
    const std::vector<scene::LightRef> lights = shadowedLights(plans, scene);
    if (lights.empty())
        throw rhi::Error(fmt::format("{}: no light has a shadow map in this frame, so there is nothing to compare",
                                     options.scene.scene));
    std::vector<LightTruth> truths;
    for (const scene::LightRef& light : lights) {
        stopIfInterrupted();
        frame.visibilityOf = light;
        renderer.render(scene.camera, frame, plans);
        const rhi::Image view = rhi::readTexture(*device, renderer.visibilityImage());
        truths.push_back({light, truth::lightLabel(scene, light), {}, truth::renderedVisibility(view), {}, 0.0f, {}});
    }
    for (const std::string& note : renderer.notes())
        fmt::print("  note: {}\n", note);
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", options.backend, messages.size(), messages[0]));

    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    const truth::RayCaster shadowRays(scene);
    const truth::CpuGBuffer gbuffer =
        truth::traceGBuffer(scene, cameraRays, scene.camera, frame.width, frame.height, progressBar("camera rays"));
    nlohmann::json report = {{"scene", options.scene.scene},
                             {"configuration", options.backend},
                             {"width", frame.width},
                             {"height", frame.height},
                             {"edgeMarginPixels", truth::kTruthEdgeMargin},
                             {"lights", nlohmann::json::array()}};
    for (LightTruth& t : truths) {
        truth::LightTruthTrace trace = truth::traceLightTruth(scene, shadowRays, gbuffer, plans, frame.shadows, t.light,
                                                              progressBar(fmt::format("'{}'", t.name)));
        t.comparison = truth::compareLightTruth(trace, shadowRays, gbuffer, t.rendered);
        t.raycast = std::move(trace.visibility);
        t.contactGapTexels =
            truth::contactGapTexels(t.comparison, gbuffer, shadowRays, trace.rays, [&](glm::vec3 position) {
                return truth::shadowTexelSize(plans, frame.shadows, scene, t.light, position);
            });
        t.contactGaps = truth::contactGapPixels(gbuffer, t.raycast, t.rendered, shadowRays, trace.rays,
                                                frame.shadows.contact.length);
        nlohmann::json entry = lightReport(scene, t);
        if (wantsSoftTruth(options, scene, plans, t.light)) {
            const truth::SoftVisibilityMap soft =
                truth::traceAreaLightVisibility(scene, shadowRays, gbuffer, truth::areaLightOf(scene, t.light),
                                                truth::kAreaLightRaysPerSide,
                                                progressBar(fmt::format("'{}' area light", t.name)));
            const truth::SoftTruthFigures figures = truth::compareSoftVisibility(soft, t.rendered);
            entry["sourceSize"] = truth::lightSourceSize(scene, t.light);
            entry["filter"] = shadows::shadowFilters()[std::size_t(truth::plannedShadowFilter(plans, t.light))].command;
            entry["penumbraPixels"] = figures.penumbraPixels;
            entry["softCompared"] = figures.compared;
            entry["softMeanAbsError"] = figures.meanAbsError;
            fmt::print("{}: source size {}, {} penumbra pixels, soft mean absolute error {:.4f} over {} pixels\n",
                       t.name, truth::lightSourceSize(scene, t.light), figures.penumbraPixels, figures.meanAbsError,
                       figures.compared);
        }
        report["lights"].push_back(std::move(entry));
    }

    // Everything is computed before the first file is written: a failure leaves no partial report.
    stopIfInterrupted();
    const std::filesystem::path out(options.out);
    writeTruthPictures(out, truths);
    parity::writeTextFile(out / "truth.json", report.dump(2) + "\n");
    for (const LightTruth& t : truths) {
        const truth::TruthComparison& c = t.comparison;
        fmt::print("{} ({} {}): agreement {} of {} pixels; truly lit {} right of {}, truly shadowed {} right of {}; "
                   "acne {}, leaks {}, contact gap {:.2f} texels; contact gaps {} of {} pixels\n",
                   t.name, scene::lightKindName(t.light.kind), t.light.index, percent(c.agreement()), c.compared(),
                   percent(c.lit.share()), c.lit.compared, percent(c.shadowed.share()), c.shadowed.compared, c.acne(),
                   c.leaks(), t.contactGapTexels, t.contactGaps.gaps, t.contactGaps.shadowed);
        if (c.dithered.compared > 0)
            fmt::print("  behind dithered casters only: {} pixels, {:.3f} of the light expected on average, {:.3f} "
                       "rendered\n",
                       c.dithered.compared, c.dithered.expectedLit(), c.dithered.renderedLit());
    }
    fmt::print("  wrote {}\n", (out / "truth.json").string());
}

} // namespace

void addTruthCommand(CLI::App& app)
{
    auto options = std::make_shared<TruthOptions>();
    CLI::App* command =
        app.add_subcommand("truth",
                           "Compare a scene's shadow maps with a CPU ray cast of the same pixels, per shadowed light: "
                           "writes raycast.png, shadowmap.png, disagreement.png (acne red, leaks blue) and truth.json");
    command->add_option("-b,--backend", options->backend, "One configuration name (vulkan, opengl-reversed, ...)")
        ->check(configurationValidator())
        ->capture_default_str();
    addSceneOptions(*command, options->scene);
    command->add_option("-o,--out", options->out, "Output folder")->required();
    addValidateFlag(*command, options->validate);
    command->callback([options] {
        installInterruptHandler();
        truth(*options);
    });
}

} // namespace penumbra::apps
