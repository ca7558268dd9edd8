#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "DrawScene.hpp"
#include "ImageFiles.hpp"
#include "RawDraws.hpp"
#include "ShadowBench.hpp"
#include "SoftShadowBench.hpp"

#include "penumbra/backends/CreateDevice.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <algorithm>
#include <map>
#include <optional>

namespace penumbra::apps {
namespace {

struct BenchOptions {
    std::vector<std::string> configurations = {"vulkan", "opengl"};
    std::vector<std::uint32_t> draws = {1000, 5000, 20000};
    double minTime = 1.0;
    std::vector<std::string> suites = {"draws", "shadows"};
    std::string json; // empty: no JSON file
};

bool wants(const BenchOptions& options, const std::string& suite)
{
    return std::find(options.suites.begin(), options.suites.end(), suite) != options.suites.end();
}

// Prints Google Benchmark's table and keeps each run's real time per iteration.
class CollectingReporter : public benchmark::ConsoleReporter {
public:
    CollectingReporter() : ConsoleReporter(OO_Tabular) {}

    void ReportRuns(const std::vector<Run>& runs) override
    {
        for (const Run& run : runs)
            if (run.run_type == Run::RT_Iteration)
                seconds[run.run_name.function_name] =
                    run.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(run.time_unit);
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> seconds;
};

struct Case {
    std::string configuration;
    std::uint32_t draws;
    std::string rhiName, rawName;
};

void runBenchmarks(const BenchOptions& options)
{
    // Devices and scenes live until every benchmark has run.
    std::vector<std::unique_ptr<rhi::Device>> devices;
    std::vector<std::unique_ptr<DrawScene>> scenes;
    std::vector<std::unique_ptr<rhi::CommandList>> lists;
    std::vector<std::unique_ptr<RawDraws>> raws;
    std::vector<Case> cases;
    for (const std::string& configuration : wants(options, "draws") ? options.configurations : std::vector<std::string>{}) {
        rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
        desc.validation = false; // timing the driver, not the validation layer
        rhi::Device& device = *devices.emplace_back(createDevice(desc));
        for (std::uint32_t n : options.draws) {
            const DrawScene& scene = *scenes.emplace_back(std::make_unique<DrawScene>(device, n));
            rhi::CommandList& commands = *lists.emplace_back(device.createCommandList());
            RawDraws& raw = *raws.emplace_back(createRawDraws(device, scene));
            const Case c{configuration, n, fmt::format("draws/{}/rhi/{}", configuration, n),
                         fmt::format("draws/{}/raw/{}", configuration, n)};
            benchmark::RegisterBenchmark(c.rhiName.c_str(), [&device, &scene, &commands](benchmark::State& state) {
                for (auto _ : state) {
                    scene.recordRhi(commands);
                    device.submit(commands);
                }
            })->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(options.minTime);
            benchmark::RegisterBenchmark(c.rawName.c_str(), [&raw](benchmark::State& state) {
                for (auto _ : state)
                    raw.frame();
            })->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(options.minTime);
            cases.push_back(c);
        }
    }

    std::optional<ShadowBench> shadowBench;
    if (wants(options, "shadows"))
        shadowBench.emplace(options.configurations, options.minTime);

    std::optional<SoftShadowBench> softBench;
    if (wants(options, "soft"))
        softBench.emplace(options.configurations, options.minTime);
    CollectingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    nlohmann::json json = {{"draws", nlohmann::json::array()},
                           {"shadows", nlohmann::json::array()},
                           {"soft", nlohmann::json::array()}};
    if (shadowBench) {
        shadowBench->printSummary();
        json["shadows"] = shadowBench->toJson();
    }
    if (softBench) {
        softBench->printSummary();
        json["soft"] = softBench->toJson();
    }
    if (!cases.empty())
        fmt::print("\n{:<24} {:>7} {:>14} {:>14} {:>10}\n", "configuration", "draws", "rhi ns/draw", "raw ns/draw",
                   "rhi / raw");
    for (const Case& c : cases) {
        const double rhi = reporter.seconds.at(c.rhiName) * 1e9 / c.draws;
        const double raw = reporter.seconds.at(c.rawName) * 1e9 / c.draws;
        fmt::print("{:<24} {:>7} {:>14.1f} {:>14.1f} {:>10.3f}\n", c.configuration, c.draws, rhi, raw, rhi / raw);
        json["draws"].push_back({{"configuration", c.configuration},
                                 {"draws", c.draws},
                                 {"rhiNsPerDraw", rhi},
                                 {"rawNsPerDraw", raw},
                                 {"rhiOverRaw", rhi / raw}});
    }
    if (!options.json.empty()) {
        writeTextFile(options.json, json.dump(2) + "\n");
        fmt::print("wrote {}\n", options.json);
    }
}

} // namespace

void addBenchCommand(CLI::App& app)
{
    auto options = std::make_shared<BenchOptions>();
    CLI::App* bench = app.add_subcommand(
        "bench", "Time N small draws per frame through the RHI and through hand-written raw API code, and the "
                 "shadow passes of the test scene");
    bench->add_option("-s,--suites", options->suites, "draws, shadows, soft (the soft-shadow filters' lit pass)")
        ->check(CLI::IsMember({"draws", "shadows", "soft"}));
    bench->add_option("-c,--configurations", options->configurations, "Configurations to measure")
        ->check(configurationValidator());
    bench->add_option("-n,--draws", options->draws, "Draws per frame")->check(CLI::Range(1u, 1000000u));
    bench->add_option("--min-time", options->minTime, "Minimum seconds per benchmark")->check(CLI::Range(0.01, 60.0));
    bench->add_option("--json", options->json,
                      "Also write the figures to this file: {\"draws\": [{configuration, draws, rhiNsPerDraw, "
                      "rawNsPerDraw, rhiOverRaw}], \"shadows\": [{configuration, scenario, atlasPassMs, otherAtlasPassMs, litPassMs, frameMs, "
                      "casterDraws, ...}]}");
    bench->callback([options] { runBenchmarks(*options); });
}

} // namespace penumbra::apps
