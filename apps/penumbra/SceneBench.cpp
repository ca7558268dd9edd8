#include "SceneBench.hpp"

#include "penumbra/render/FrameResources.hpp"

#include "BackendOptions.hpp"
#include "BenchSeries.hpp"
#include "Interrupt.hpp"
#include "RenderSettings.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/ReferenceLitPass.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/Posing.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <optional>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace penumbra::apps {
namespace {

constexpr std::size_t kPasses = std::size(kBenchPassNames);

// How far the animation advances per drawn frame (warm-up frames included): a 60 Hz display's frame.
constexpr float kFrameSeconds = 1.0f / 60.0f;

// The animation --time or --animation plays, where given: frame i is posed at start + i * kFrameSeconds, looping over
// the animation's duration, so that each frame skins anew and the tile caches see the pose change.
struct BenchAnimation {
    std::uint32_t animation = 0;
    float start = 0.0f;

    float timeOfFrame(std::uint32_t frame, const scene::Rig& rig) const
    {
        const float duration = rig.animations[animation].duration();
        const float time = start + float(frame) * kFrameSeconds;
        return duration > 0.0f ? std::fmod(time, duration) : time;
    }
};

std::optional<BenchAnimation> benchAnimation(const SceneOptions& options, const scene::Scene& scene)
{
    if (!options.time && options.animation.empty())
        return std::nullopt;
    return BenchAnimation{scene::findAnimation(scene.rig, options.animation.empty() ? "0" : options.animation),
                          options.time.value_or(0.0f)};
}

struct ConfigurationResult {
    std::string configuration;
    Series frame;
    Series planning; // CPU: render::FrameStats::planningMs
    Series recording; // CPU: render::FrameStats::recordingMs
    Series cpuFrame; // planning + recording
    Series localTilesDrawn, localTilesCached, localLightsRedrawn;
    // Why the measured frames' local lights were drawn again: how often each reason came (the text after the light's
    // name in render::FrameStats::localShadowUpdates).
    std::map<std::string, std::uint32_t> redrawReasons;
    std::array<Series, kPasses> passes;
    render::FrameStats last;
    // From creating the device to the end of the first frame: uploads, mip chains, pipelines and one frame, what a
    // user waits for after the file is read.
    double firstFrameSeconds = 0.0;
};

// The reference lit pass draws every object with a draw call of its own. On lavapipe the commands of 10^6 draws are
// freed afterwards as millions of small heap blocks, which glibc's malloc keeps in fast bins and consolidates at the
// next large allocation: 13 to 77 ms billed to the next measured frame's planning at 10^6 instances. Without fast bins
// (mallopt(3), M_MXFAST 0) a block is merged as it is freed, inside the reference frame, which is not measured.
void mergeFreedBlocksAtOnce()
{
#if defined(__GLIBC__)
    mallopt(M_MXFAST, 0);
#endif
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each pass's GPU time of one frame, in kBenchPassNames order; 0 for a pass the frame does not draw. An atlas's
// time includes the copy of its cached static tiles.
std::array<double, kPasses> passTimes(const render::FrameStats& s, double referenceMs)
{
    namespace frame = render::frame;
    const auto ms = [&](std::string_view pass) { return s.passMs(pass).value_or(0.0); };
    return {ms(frame::kDepthPrepass) + ms(frame::kReceiverPrepass) + ms(frame::kSingleSampledDepthPrepass),
            ms(frame::kDirectionalStaticTilesPass) + ms(frame::kDirectionalAtlasPass),
            ms(frame::kLocalStaticTilesPass) + ms(frame::kLocalAtlasPass),
            ms(frame::kScreenSpaceShadowsPass),
            ms(frame::kLitPass),
            ms(frame::kResolvePass),
            referenceMs,
            ms(frame::kStaticMapsPass),
            ms(frame::kContactShadowsPass),
            ms(frame::kDepthReductionPass),
            ms(frame::kCasterCullingPass),
            ms(frame::kLightClusterPass),
            ms(frame::kViewCullingPass)};
}

ConfigurationResult benchConfiguration(const std::string& configuration, const scene::Scene& loaded,
                                       const render::FrameDesc& frame, const SceneBenchOptions& options,
                                       const std::optional<shadows::StaticShadowBake>& bake)
{
    scene::Scene scene = loaded; // posed anew each frame where an animation plays
    const std::optional<BenchAnimation> animation = benchAnimation(options.scene, scene);
    const auto deviceStart = std::chrono::steady_clock::now();
    auto device = createDevice(toolDeviceDesc(configuration, options.validate));
    if (!device->capabilities().timestamps)
        throw rhi::Error(
            fmt::format("{}: the device has no timestamp queries, so passes cannot be timed", configuration));
    render::SceneRenderer renderer(*device, scene);
    if (bake)
        renderer.useBakedShadows(*bake);
    const auto reference = std::make_shared<render::ReferenceLitPass>(*device, renderer, scene.camera, frame);
    renderer.addTexture(std::string(render::ReferenceLitPass::kImage), reference->image());
    renderer.addTexture(std::string(render::ReferenceLitPass::kDepth), reference->depth());
    renderer.addPass(reference, render::PassPlacement::after(std::string(render::frame::kLitPass)));
    ConfigurationResult result{configuration, {}, {}, {}, {}, {}};
    const std::uint32_t total = options.warmup + options.frames;
    for (std::uint32_t i = 0; i < total; ++i) {
        stopIfInterrupted();
        if (animation)
            scene::poseScene(scene, animation->animation, animation->timeOfFrame(i, scene.rig));
        if (options.scene.movingCars)
            scenes::driveStreetCars(scene, static_cast<float>(i) * kFrameSeconds);
        // Each measured frame leaves the reference lit pass out, so that its wall time and pass times are the
        // renderer's alone; the reference's GPU time comes from a second frame with it in, after the lit pass on the
        // same plan and atlas.
        reference->setEnabled(false);
        const auto start = std::chrono::steady_clock::now();
        render::FrameStats stats = renderer.render(scene.camera, frame);
        const double wallMs = 1000.0 * secondsSince(start);
        if (i == 0)
            result.firstFrameSeconds = secondsSince(deviceStart);
        reference->setEnabled(true);
        const double referenceMs =
            renderer.render(scene.camera, frame).passMs(render::ReferenceLitPass::kName).value_or(0.0);
        showBenchProgress(configuration, i + 1, total);
        if (i < options.warmup)
            continue;
        result.frame.values.push_back(wallMs);
        result.planning.values.push_back(stats.planningMs);
        result.recording.values.push_back(stats.recordingMs);
        result.cpuFrame.values.push_back(stats.planningMs + stats.recordingMs);
        result.localTilesDrawn.values.push_back(stats.localTilesDrawn);
        result.localTilesCached.values.push_back(stats.localTilesCached);
        result.localLightsRedrawn.values.push_back(static_cast<double>(stats.localShadowUpdates.size()));
        for (const std::string& update : stats.localShadowUpdates) {
            const std::size_t reason = update.find("): ");
            ++result.redrawReasons[reason == std::string::npos ? update : update.substr(reason + 3)];
        }
        const std::array<double, kPasses> times = passTimes(stats, referenceMs);
        for (std::size_t p = 0; p < kPasses; ++p)
            result.passes[p].values.push_back(times[p]);
        result.last = std::move(stats);
    }
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return result;
}

std::size_t passIndex(std::string_view name)
{
    return static_cast<std::size_t>(std::find(std::begin(kBenchPassNames), std::end(kBenchPassNames), name) -
                                    std::begin(kBenchPassNames));
}

// Our passes that the reference lit pass stands for: the depth prepass and the lit pass.
double litOverReference(const ConfigurationResult& r)
{
    const double reference = r.passes[passIndex("reference")].median();
    const double ours = r.passes[passIndex("depth")].median() + r.passes[passIndex("screenSpaceShadows")].median() +
                        r.passes[passIndex("lit")].median();
    return reference > 0.0 ? ours / reference : 0.0;
}

// How the static shadow maps came: "everyFrame" (none), "onChange", "onDemand" or "baked".
std::string staticMapsMode(const render::FrameDesc& frame, const SceneBenchOptions& options)
{
    if (!options.scene.baked.empty())
        return "baked";
    switch (frame.shadows.staticMaps.update) {
    case shadows::StaticShadowUpdate::OnChange:
        return "onChange";
    case shadows::StaticShadowUpdate::OnDemand:
        return "onDemand";
    case shadows::StaticShadowUpdate::EveryFrame:
        break;
    }
    return "everyFrame";
}

// --lights N, or null: the scene's own local lights.
nlohmann::json benchLightsOf(const SceneBenchOptions& options)
{
    return options.scene.localLights ? nlohmann::json(*options.scene.localLights) : nlohmann::json();
}

nlohmann::json toJson(const ConfigurationResult& r, const SceneBenchOptions& options, const render::FrameDesc& frame,
                      double loadSeconds)
{
    nlohmann::json passes = nlohmann::json::object(), mins = nlohmann::json::object(), maxs = nlohmann::json::object();
    for (std::size_t p = 0; p < kPasses; ++p) {
        passes[kBenchPassNames[p]] = r.passes[p].median();
        mins[kBenchPassNames[p]] = r.passes[p].min();
        maxs[kBenchPassNames[p]] = r.passes[p].max();
    }
    return {{"configuration", r.configuration},
            {"scene", options.scene.scene},
            {"lights", benchLightsOf(options)},
            {"width", frame.width},
            {"height", frame.height},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"depthPrepass", frame.depthPrepass},
            {"msaa", frame.msaa},
            {"shadowPath", shadowPathName(frame.shadowPath)},
            {"cascadeCount", frame.shadows.directional.cascadeCount},
            {"atlasSize", frame.shadows.directional.atlasSize},
            {"culling", frame.shadows.culling == shadows::CasterCullingMode::Gpu ? "gpu" : "cpu"},
            {"clusterBuild", frame.shadows.local.clusterBuild == shadows::LightClusterBuild::Gpu ? "gpu" : "cpu"},
            {"frameMs", r.frame.median()},
            {"frameMsMin", r.frame.min()},
            {"frameMsMax", r.frame.max()},
            {"passes", passes},
            {"passesMin", mins},
            {"passesMax", maxs},
            {"litOverReference", litOverReference(r)},
            {"instancing", frame.instancedDraws},
            {"cpuMs", {{"planning", r.planning.median()}, {"recording", r.recording.median()}}},
            {"cpuMsMax", {{"planning", r.planning.max()}, {"recording", r.recording.max()}}},
            {"draws", {{"depth", r.last.depthPrepassDraws}, {"lit", r.last.litDraws}}},
            {"casterDraws", r.last.casterDraws + r.last.localCasterDraws},
            {"staticCasterDraws", r.last.staticCasterDraws},
            {"staticMaps", staticMapsMode(frame, options)},
            {"cpuFrameMs", r.cpuFrame.median()},
            {"shadowedLights", r.last.shadowedLights},
            {"lightsWithoutShadow", r.last.lightsWithoutShadow},
            {"localTilesDrawn", r.localTilesDrawn.median()},
            {"localTilesCached", r.localTilesCached.median()},
            {"movingCars", options.scene.movingCars},
            {"localLightsRedrawn", r.localLightsRedrawn.median()},
            {"localLightsRedrawnMax", r.localLightsRedrawn.max()},
            {"redrawReasons", r.redrawReasons},
            {"loadSeconds", loadSeconds},
            {"firstFrameSeconds", r.firstFrameSeconds}};
}

void printTable(const std::vector<ConfigurationResult>& results, const SceneBenchOptions& options,
                const render::FrameDesc& frame, double loadSeconds)
{
    fmt::print("\n{} at {}x{}, {} cascades in a {}^2 atlas, depth prepass {}, msaa {}, {} shadows; {} frames after {} "
               "warm-up, instancing {} (medians; GPU timestamps per pass, wall time per frame)\n",
               options.scene.scene, frame.width, frame.height, frame.shadows.directional.cascadeCount,
               frame.shadows.directional.atlasSize, frame.depthPrepass ? "on" : "off", frame.msaa,
               shadowPathName(frame.shadowPath), options.frames, options.warmup, frame.instancedDraws ? "on" : "off");
    fmt::print("{:<24} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>11} {:>9}\n", "configuration", "frame ms",
               "depth", "atlas", "local", "ss shadow", "lit", "resolve", "reference", "ours / ref", "frame max");
    for (const ConfigurationResult& r : results)
        fmt::print(
            "{:<24} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f} {:>11.3f} {:>9.2f}\n",
            r.configuration, r.frame.median(), r.passes[passIndex("depth")].median(),
            r.passes[passIndex("directionalAtlas")].median(), r.passes[passIndex("otherAtlas")].median(),
            r.passes[passIndex("screenSpaceShadows")].median(), r.passes[passIndex("lit")].median(),
            r.passes[passIndex("resolve")].median(), r.passes[passIndex("reference")].median(), litOverReference(r),
            r.frame.max());
    if (frame.shadows.contact.shadows == shadows::Toggle::On)
        for (const ConfigurationResult& r : results) {
            const double lit = r.passes[passIndex("lit")].median();
            const double contact = r.passes[passIndex("contactShadows")].median();
            fmt::print("{:<24} contact shadows {:.2f} ms, {:.1f}% of the lit pass\n", r.configuration, contact,
                       lit > 0.0 ? 100.0 * contact / lit : 0.0);
        }
    fmt::print("{:<24} {:>12} {:>13} {:>11} {:>10} {:>12}\n", "configuration", "planning ms", "recording ms",
               "depth draws", "lit draws", "caster draws");
    for (const ConfigurationResult& r : results)
        fmt::print("{:<24} {:>12.2f} {:>13.2f} {:>11} {:>10} {:>12}\n", r.configuration, r.planning.median(),
                   r.recording.median(), r.last.depthPrepassDraws, r.last.litDraws,
                   r.last.casterDraws + r.last.localCasterDraws);
    fmt::print("{:<24} {:>8} {:>9} {:>15} {:>12} {:>12} {:>13}\n", "configuration", "shadowed", "unshadowed",
               "local tiles drawn", "tiles cached", "cpu frame ms", "local atlas ms");
    for (const ConfigurationResult& r : results)
        fmt::print("{:<24} {:>8} {:>9} {:>15.1f} {:>12.1f} {:>12.2f} {:>13.2f}\n", r.configuration,
                   r.last.shadowedLights, r.last.lightsWithoutShadow, r.localTilesDrawn.median(),
                   r.localTilesCached.median(), r.cpuFrame.median(), r.passes[passIndex("otherAtlas")].median());
    for (const ConfigurationResult& r : results)
        for (const auto& [reason, count] : r.redrawReasons)
            fmt::print("{}: {} light redraws over the measured frames: {}\n", r.configuration, count, reason);
    // directional.projection depthFit: the reduction's GPU time and the plan's CPU time, which holds the fit, against
    // the frame, apart and together (the plan's other work is in the sum too, so it bounds the fit's share).
    for (const ConfigurationResult& r : results)
        if (const double reduction = r.passes[passIndex("depthFit")].median(); reduction > 0.0)
            fmt::print("{:<24} depth fit: reduction {:.3f} ms ({:.1f} % of the frame), planning with the fit {:.3f} ms "
                       "({:.1f} %), together {:.1f} %\n",
                       r.configuration, reduction, 100.0 * reduction / r.frame.median(), r.planning.median(),
                       100.0 * r.planning.median() / r.frame.median(),
                       100.0 * (reduction + r.planning.median()) / r.frame.median());
    // local.clusterBuild gpu: the light cluster build's GPU time against the lit pass that reads its lists.
    for (const ConfigurationResult& r : results)
        if (const double build = r.passes[passIndex("lightClusters")].median(); build > 0.0)
            fmt::print("{:<24} light clusters built on the GPU: {:.3f} ms ({:.1f} % of the lit pass)\n",
                       r.configuration, build, 100.0 * build / std::max(r.passes[passIndex("lit")].median(), 1e-9));
    // Loading: the file read once, then per configuration its device, uploads, pipelines and first frame.
    for (const ConfigurationResult& r : results)
        fmt::print("{:<24} loading {:.2f} s, device to first frame {:.2f} s: the first picture {:.2f} s after the "
                   "file was opened\n",
                   r.configuration, loadSeconds, r.firstFrameSeconds, loadSeconds + r.firstFrameSeconds);
    if (results.size() == 2 && results[1].frame.median() > 0.0)
        fmt::print("{} / {} frame time: {:.3f}\n", results[0].configuration, results[1].configuration,
                   results[0].frame.median() / results[1].frame.median());
}

// One light count (or the scene's own lights): every configuration, a table and a JSON row each.
void benchLights(const SceneBenchOptions& options, nlohmann::json& rows)
{
    const std::vector<std::string> configurations = expandBackends(options.backends);
    const auto loadStart = std::chrono::steady_clock::now();
    const LoadedScene loaded = loadScene(options.scene);
    const double loadSeconds = secondsSince(loadStart);
    const render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    const std::optional<shadows::StaticShadowBake> bake = loadBake(options.scene);
    for (const std::string& note : loaded.notes)
        fmt::print("{}: {}\n", options.scene.scene, note);
    mergeFreedBlocksAtOnce();
    std::vector<ConfigurationResult> results;
    for (const std::string& configuration : configurations)
        results.push_back(benchConfiguration(configuration, loaded.scene, frame, options, bake));
    printTable(results, options, frame, loadSeconds);
    for (const std::string& note : results.front().last.notes)
        fmt::print("  note: {}\n", note);
    for (const ConfigurationResult& r : results)
        rows.push_back(toJson(r, options, frame, loadSeconds));
}

} // namespace

void showBenchProgress(const std::string& configuration, std::uint32_t done, std::uint32_t total)
{
    fmt::print(stderr, "\rbench {}: frame {}/{}", configuration, done, total);
    if (done == total)
        fmt::print(stderr, "\n");
    std::fflush(stderr);
}

nlohmann::json runSceneBench(const SceneBenchOptions& options)
{
    nlohmann::json rows = nlohmann::json::array();
    if (options.lightCounts.empty())
        benchLights(options, rows);
    for (const std::uint32_t lights : options.lightCounts) {
        SceneBenchOptions one = options;
        one.scene.localLights = lights;
        benchLights(one, rows);
    }
    return {{"scene", rows}};
}

} // namespace penumbra::apps
