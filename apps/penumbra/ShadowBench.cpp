#include "ShadowBench.hpp"

#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::apps {
namespace {

// What a benchmark renders: the shadow test scene with its four directional lights, or the same
// geometry lit only by spot or point lights to time the local atlas (and the cube maps).
struct Scenario {
    std::string name;
    scene::Scene scene;
    render::FrameDesc frame;
};

render::FrameDesc benchFrame()
{
    render::FrameDesc frame;
    frame.width = 1280;
    frame.height = 720;
    frame.shadows.directional.cascadeCount = 4;
    frame.shadows.directional.atlasSize = 2048;
    frame.shadows.directional.filter = shadows::ShadowFilter::PCF5x5;
    frame.shadows.local.atlasSize = 2048;
    frame.shadows.local.filter = shadows::ShadowFilter::PCF5x5;
    return frame;
}

scene::Scene localLightsOnly()
{
    scene::Scene scene = scenes::makeMixedLightsScene();
    scene.lights.clear();
    scene.spotLights.clear();
    scene.pointLights.clear();
    return scene;
}

// A 4 x 4 grid of spot lights 8 units up, each aimed at the ground below it: the local atlas's 16 tiles.
scene::Scene sixteenSpots()
{
    scene::Scene scene = localLightsOnly();
    for (int i = 0; i < 16; ++i) {
        const glm::vec3 position{-9.0f + 6.0f * float(i % 4), 8.0f, -6.0f + 6.0f * float(i / 4)};
        scene.spotLights.push_back({.name = fmt::format("spot {}", i),
                                    .intensity = 20.0f,
                                    .position = position,
                                    .direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)),
                                    .range = 16.0f});
    }
    return scene;
}

scene::Scene twoPoints()
{
    scene::Scene scene = localLightsOnly();
    scene.pointLights = scenes::makeMixedLightsScene().pointLights;
    return scene;
}

std::vector<Scenario> scenarios()
{
    render::FrameDesc cubeMaps = benchFrame();
    cubeMaps.shadows.local.pointMode = shadows::PointShadowMode::CubeMap;
    return {{"directional", scenes::makeShadowTestScene(), benchFrame()},
            {"16 spot tiles", sixteenSpots(), benchFrame()},
            {"2 points, 12 tiles", twoPoints(), benchFrame()},
            {"2 points, cube maps", twoPoints(), cubeMaps}};
}

} // namespace

struct ShadowBench::Case {
    std::string configuration;
    std::string scenario;
    std::unique_ptr<rhi::Device> device;
    scene::Scene scene;
    std::unique_ptr<render::SceneRenderer> renderer;
    render::FrameDesc frame;
    double atlasMs = 0.0, localMs = 0.0, litMs = 0.0, frameMs = 0.0;
    std::uint32_t frames = 0;
    render::FrameStats last;
};

ShadowBench::ShadowBench(const std::vector<std::string>& configurations, double minTime)
{
    for (const std::string& configuration : configurations) {
        rhi::DeviceDesc desc = toolDeviceDesc(configuration);
        desc.validation = false; // timing the driver, not the API's validation layer
        for (Scenario& scenario : scenarios()) {
            auto c = std::make_unique<Case>();
            c->configuration = configuration;
            c->scenario = scenario.name;
            c->device = createDevice(desc);
            c->scene = std::move(scenario.scene);
            c->renderer = std::make_unique<render::SceneRenderer>(*c->device, c->scene);
            c->frame = scenario.frame;
            Case& bench = *c;
            const std::string name = fmt::format("shadows/{}/{}", scenario.name, configuration);
            benchmark::RegisterBenchmark(
                name.c_str(),
                [&bench](benchmark::State& state) {
                    for (auto _ : state) {
                        const auto start = std::chrono::steady_clock::now();
                        bench.last = bench.renderer->render(bench.scene.camera, bench.frame);
                        bench.frameMs +=
                            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                        bench.atlasMs += bench.last.passMs(render::frame::kDirectionalAtlasPass).value_or(0.0);
                        bench.localMs += bench.last.passMs(render::frame::kLocalAtlasPass).value_or(0.0);
                        bench.litMs += bench.last.passMs(render::frame::kLitPass).value_or(0.0);
                        ++bench.frames;
                    }
                    state.counters["atlas_ms"] = bench.atlasMs / bench.frames;
                    state.counters["other_atlas_ms"] = bench.localMs / bench.frames;
                    state.counters["lit_ms"] = bench.litMs / bench.frames;
                    state.counters["caster_draws"] = bench.last.casterDraws + bench.last.localCasterDraws;
                })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->MinTime(minTime);
            cases_.push_back(std::move(c));
        }
    }
}

ShadowBench::~ShadowBench() = default;

nlohmann::json ShadowBench::toJson() const
{
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& c : cases_) {
        const double frames = std::max<std::uint32_t>(c->frames, 1);
        rows.push_back({{"configuration", c->configuration},
                        {"scenario", c->scenario},
                        {"width", c->frame.width},
                        {"height", c->frame.height},
                        {"frames", c->frames},
                        {"atlasPassMs", c->atlasMs / frames},
                        {"otherAtlasPassMs", c->localMs / frames},
                        {"litPassMs", c->litMs / frames},
                        {"frameMs", c->frameMs / frames},
                        {"casterDraws", c->last.casterDraws},
                        {"otherCasterDraws", c->last.localCasterDraws},
                        {"casterDrawsWithoutCullingBias", c->last.casterDrawsWithoutCullingBias}});
    }
    return rows;
}

void ShadowBench::printSummary() const
{
    fmt::print("\n1280x720; directional: 4 cascades, 2048 atlas, PCF 5x5; spot and point: 2048 atlas (512 cube faces), "
               "PCF 5x5 (GPU timestamps, mean per frame)\n");
    fmt::print("{:<24} {:<20} {:>9} {:>9} {:>9} {:>10} {:>11} {:>13} {:>13}\n", "configuration", "scenario", "atlas ms",
               "local ms", "lit ms", "frame ms", "atlas/frame", "caster draws", "without bias");
    for (const auto& c : cases_) {
        const double frames = std::max<std::uint32_t>(c->frames, 1);
        const double atlas = c->atlasMs / frames, local = c->localMs / frames, lit = c->litMs / frames,
                     frame = c->frameMs / frames;
        fmt::print("{:<24} {:<20} {:>9.2f} {:>9.2f} {:>9.2f} {:>10.2f} {:>11.3f} {:>13} {:>13}\n", c->configuration,
                   c->scenario, atlas, local, lit, frame, (atlas + local) / frame,
                   c->last.casterDraws + c->last.localCasterDraws, c->last.casterDrawsWithoutCullingBias);
    }
    if (!cases_.empty()) {
        const render::FrameStats& s = cases_.front()->last;
        fmt::print("culling bias: {} of {} directional caster draws issued ({:.3f})\n", s.casterDraws,
                   s.casterDrawsWithoutCullingBias,
                   double(s.casterDraws) / std::max<std::uint32_t>(s.casterDrawsWithoutCullingBias, 1));
    }
}

} // namespace penumbra::apps
