#include "SoftShadowBench.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

constexpr float kSunDiameterDegrees = 3.0f;

struct Variant {
    std::string name;
    shadows::ShadowFilter filter;
    std::uint32_t blockerSamples;
    std::uint32_t filterSamples;
};

const std::vector<Variant>& variants()
{
    static const std::vector<Variant> list{{"pcf5x5", shadows::ShadowFilter::PCF5x5, 16, 16},
                                           {"poisson 16", shadows::ShadowFilter::Poisson, 16, 16},
                                           {"pcss 16+16", shadows::ShadowFilter::PCSS, 16, 16},
                                           {"pcss 32+32", shadows::ShadowFilter::PCSS, 32, 32},
                                           {"pcss 32+64", shadows::ShadowFilter::PCSS, 32, 64}};
    return list;
}

} // namespace

struct SoftShadowBench::Case {
    std::string configuration;
    std::string variant;
    std::unique_ptr<rhi::Device> device;
    scene::Scene scene;
    std::unique_ptr<render::SceneRenderer> renderer;
    render::FrameDesc frame;
    double litMs = 0.0;
    std::uint32_t frames = 0;

    double meanLitMs() const { return litMs / std::max<std::uint32_t>(frames, 1); }
};

SoftShadowBench::SoftShadowBench(const std::vector<std::string>& configurations, double minTime)
{
    for (const std::string& configuration : configurations) {
        rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
        desc.validation = false; // timing the driver, not the validation layer
        for (const Variant& variant : variants()) {
            auto c = std::make_unique<Case>();
            c->configuration = configuration;
            c->variant = variant.name;
            c->device = createDevice(desc);
            c->scene = scenes::makeShadowTestScene();
            for (scene::DirectionalLight& light : c->scene.lights)
                light.angularDiameter = kSunDiameterDegrees;
            c->renderer = std::make_unique<render::SceneRenderer>(*c->device, c->scene);
            c->frame.width = 1280;
            c->frame.height = 720;
            c->frame.shadows.directional.atlasSize = 2048;
            c->frame.shadows.directional.filter = variant.filter;
            c->frame.shadows.soft.blockerSamples = variant.blockerSamples;
            c->frame.shadows.soft.filterSamples = variant.filterSamples;
            cases_.push_back(std::move(c));
        }
        // One benchmark per configuration that draws a frame of every filter in turn: on a machine shared with other
        // work a software rasterizer's times follow the others' load, which drifts over seconds; interleaved, every
        // filter sees the same load and the ratios to PCF 5x5 keep, where filters timed one after the other did not.
        std::vector<Case*> round;
        for (const auto& c : cases_)
            if (c->configuration == configuration)
                round.push_back(c.get());
        const std::string name = fmt::format("soft/{}", configuration);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [round](benchmark::State& state) {
                                         for (auto _ : state)
                                             for (Case* bench : round) {
                                                 bench->litMs +=
                                                     bench->renderer->render(bench->scene.camera, bench->frame)
                                                         .passMs(render::frame::kLitPass)
                                                         .value_or(0.0);
                                                 ++bench->frames;
                                             }
                                     })
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond)
            ->MinTime(minTime);
    }
}

SoftShadowBench::~SoftShadowBench() = default;

namespace {

// The PCF 5x5 case of the same configuration: the ratios' denominator.
template <typename Cases>
double baselineMs(const Cases& cases, const std::string& configuration)
{
    for (const auto& c : cases)
        if (c->configuration == configuration && c->variant == variants().front().name)
            return c->meanLitMs();
    return 0.0;
}

} // namespace

nlohmann::json SoftShadowBench::toJson() const
{
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& c : cases_) {
        const double baseline = baselineMs(cases_, c->configuration);
        rows.push_back({{"configuration", c->configuration},
                        {"variant", c->variant},
                        {"frames", c->frames},
                        {"litPassMs", c->meanLitMs()},
                        {"overPcf5x5", baseline > 0.0 ? c->meanLitMs() / baseline : 0.0}});
    }
    return rows;
}

void SoftShadowBench::printSummary() const
{
    fmt::print("\n1280x720, shadow test scene, 4 suns {} degrees wide, 4 cascades, 2048 atlas: lit pass (GPU "
               "timestamps, mean per frame)\n",
               kSunDiameterDegrees);
    fmt::print("{:<24} {:<12} {:>9} {:>12}\n", "configuration", "filter", "lit ms", "/ pcf5x5");
    for (const auto& c : cases_) {
        const double baseline = baselineMs(cases_, c->configuration);
        fmt::print("{:<24} {:<12} {:>9.2f} {:>12.3f}\n", c->configuration, c->variant, c->meanLitMs(),
                   baseline > 0.0 ? c->meanLitMs() / baseline : 0.0);
    }
}

} // namespace penumbra::apps
