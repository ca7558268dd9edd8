#include "ShadowBench.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <fmt/format.h>

namespace penumbra::apps {

struct ShadowBench::Case {
    std::string configuration;
    std::unique_ptr<rhi::Device> device;
    scene::Scene scene;
    std::unique_ptr<render::SceneRenderer> renderer;
    render::FrameDesc frame;
    double atlasMs = 0.0, litMs = 0.0, frameMs = 0.0;
    std::uint32_t frames = 0;
    render::FrameStats last;
};

ShadowBench::ShadowBench(const std::vector<std::string>& configurations, double minTime)
{
    for (const std::string& configuration : configurations) {
        auto c = std::make_unique<Case>();
        c->configuration = configuration;
        rhi::DeviceDesc desc = rhi::parseConfiguration(configuration);
        desc.validation = false; // timing the driver, not the validation layer
        c->device = createDevice(desc);
        c->scene = scene::makeShadowTestScene();
        c->renderer = std::make_unique<render::SceneRenderer>(*c->device, c->scene);
        c->frame.width = 1280;
        c->frame.height = 720;
        c->frame.shadows.directional.cascadeCount = 4;
        c->frame.shadows.directional.atlasSize = 2048;
        c->frame.shadows.directional.filter = shadows::ShadowFilter::PCF5x5;
        Case& bench = *c;
        benchmark::RegisterBenchmark(fmt::format("shadows/{}", configuration).c_str(), [&bench](benchmark::State& state) {
            for (auto _ : state) {
                const auto start = std::chrono::steady_clock::now();
                bench.last = bench.renderer->render(bench.scene.camera, bench.frame);
                bench.frameMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                bench.atlasMs += bench.last.atlasPassMs.value_or(0.0);
                bench.litMs += bench.last.litPassMs.value_or(0.0);
                ++bench.frames;
            }
            state.counters["atlas_ms"] = bench.atlasMs / bench.frames;
            state.counters["lit_ms"] = bench.litMs / bench.frames;
            state.counters["caster_draws"] = bench.last.casterDraws;
        })->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(minTime);
        cases_.push_back(std::move(c));
    }
}

ShadowBench::~ShadowBench() = default;

nlohmann::json ShadowBench::toJson() const
{
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& c : cases_) {
        const double frames = std::max<std::uint32_t>(c->frames, 1);
        rows.push_back({{"configuration", c->configuration},
                        {"width", c->frame.width},
                        {"height", c->frame.height},
                        {"frames", c->frames},
                        {"atlasPassMs", c->atlasMs / frames},
                        {"litPassMs", c->litMs / frames},
                        {"frameMs", c->frameMs / frames},
                        {"casterDraws", c->last.casterDraws},
                        {"casterDrawsWithoutCullingBias", c->last.casterDrawsWithoutCullingBias}});
    }
    return rows;
}

void ShadowBench::printSummary() const
{
    fmt::print("\nshadow test scene, 1280x720, 4 cascades, 2048 atlas, PCF 5x5 (GPU timestamps, mean of {} frames)\n",
               cases_.empty() ? 0 : cases_.front()->frames);
    fmt::print("{:<24} {:>10} {:>10} {:>10} {:>12} {:>14} {:>14}\n", "configuration", "atlas ms", "lit ms", "frame ms",
               "atlas/frame", "caster draws", "without bias");
    for (const auto& c : cases_) {
        const double frames = std::max<std::uint32_t>(c->frames, 1);
        const double atlas = c->atlasMs / frames, lit = c->litMs / frames, frame = c->frameMs / frames;
        fmt::print("{:<24} {:>10.2f} {:>10.2f} {:>10.2f} {:>12.3f} {:>14} {:>14}\n", c->configuration, atlas, lit, frame,
                   atlas / frame, c->last.casterDraws, c->last.casterDrawsWithoutCullingBias);
    }
    if (!cases_.empty()) {
        const render::FrameStats& s = cases_.front()->last;
        fmt::print("culling bias: {} of {} caster draws issued ({:.3f})\n", s.casterDraws,
                   s.casterDrawsWithoutCullingBias,
                   double(s.casterDraws) / std::max<std::uint32_t>(s.casterDrawsWithoutCullingBias, 1));
    }
}

} // namespace penumbra::apps
