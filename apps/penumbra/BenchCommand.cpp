#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "DrawScene.hpp"
#include "Interrupt.hpp"
#include "RawDraws.hpp"
#include "SceneBench.hpp"
#include "ShadowBench.hpp"
#include "SoftShadowBench.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/parity/ImageFiles.hpp"

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

    // Called after each benchmark: an interruption stops the run here, before the next one starts.
    void ReportRuns(const std::vector<Run>& runs) override
    {
        stopIfInterrupted();
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
    std::string rhiName, validatedName, rawName;
};

void runBenchmarks(const BenchOptions& options)
{
    // Devices and scenes live until every benchmark has run.
    std::vector<std::unique_ptr<rhi::Device>> devices;
    std::vector<std::unique_ptr<DrawScene>> scenes;
    std::vector<std::unique_ptr<rhi::CommandList>> lists;
    std::vector<std::unique_ptr<RawDraws>> raws;
    std::vector<Case> cases;
    for (const std::string& configuration :
         wants(options, "draws") ? options.configurations : std::vector<std::string>{}) {
        rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
        desc.validation = false; // timing the driver, not the API's validation layer
        desc.validateUsage = false;
        rhi::Device& device = *devices.emplace_back(createDevice(desc));
        // The same draws through the RHI's own validation layer: its overhead is validated / rhi.
        desc.validateUsage = true;
        rhi::Device& validatedDevice = *devices.emplace_back(createDevice(desc));
        const auto registerRhi = [&](const std::string& name, rhi::Device& target, std::uint32_t n) {
            const DrawScene& scene = *scenes.emplace_back(std::make_unique<DrawScene>(target, n));
            rhi::CommandList& commands = *lists.emplace_back(target.createCommandList());
            benchmark::RegisterBenchmark(name.c_str(),
                                         [&target, &scene, &commands](benchmark::State& state) {
                                             for (auto _ : state) {
                                                 scene.recordRhi(commands);
                                                 target.submit(commands);
                                             }
                                         })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->MinTime(options.minTime);
            return &scene;
        };
        for (std::uint32_t n : options.draws) {
            const Case c{configuration, n, fmt::format("draws/{}/rhi/{}", configuration, n),
                         fmt::format("draws/{}/rhi-validated/{}", configuration, n),
                         fmt::format("draws/{}/raw/{}", configuration, n)};
            const DrawScene& scene = *registerRhi(c.rhiName, device, n);
            registerRhi(c.validatedName, validatedDevice, n);
            RawDraws& raw = *raws.emplace_back(createRawDraws(device, scene));
            benchmark::RegisterBenchmark(c.rawName.c_str(),
                                         [&raw](benchmark::State& state) {
                                             for (auto _ : state)
                                                 raw.frame();
                                         })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->MinTime(options.minTime);
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
        fmt::print("\n{:<24} {:>7} {:>14} {:>14} {:>10} {:>14} {:>10}\n", "configuration", "draws", "rhi ns/draw",
                   "raw ns/draw", "rhi / raw", "validated", "val. / rhi");
    for (const Case& c : cases) {
        const double rhi = reporter.seconds.at(c.rhiName) * 1e9 / c.draws;
        const double validated = reporter.seconds.at(c.validatedName) * 1e9 / c.draws;
        const double raw = reporter.seconds.at(c.rawName) * 1e9 / c.draws;
        fmt::print("{:<24} {:>7} {:>14.1f} {:>14.1f} {:>10.3f} {:>14.1f} {:>10.3f}\n", c.configuration, c.draws, rhi,
                   raw, rhi / raw, validated, validated / rhi);
        json["draws"].push_back({{"configuration", c.configuration},
                                 {"draws", c.draws},
                                 {"rhiNsPerDraw", rhi},
                                 {"rawNsPerDraw", raw},
                                 {"rhiOverRaw", rhi / raw},
                                 {"validatedNsPerDraw", validated},
                                 {"validatedOverRhi", validated / rhi}});
    }
    stopIfInterrupted();
    if (!options.json.empty()) {
        parity::writeTextFile(options.json, json.dump(2) + "\n");
        fmt::print("wrote {}\n", options.json);
    }
}

} // namespace

void addBenchCommand(CLI::App& app)
{
    auto options = std::make_shared<BenchOptions>();
    auto scene = std::make_shared<SceneBenchOptions>();
    CLI::App* bench = app.add_subcommand(
        "bench", "Time N small draws per frame through the RHI (without and with its validation layer) and "
                 "through hand-written raw API code, and the shadow passes of the test scene; or, with --scene, "
                 "every pass of any scene's frames");
    CLI::Option* suites =
        bench->add_option("-s,--suites", options->suites, "draws, shadows, soft (the soft-shadow filters' lit pass)")
            ->check(CLI::IsMember({"draws", "shadows", "soft"}));
    CLI::Option* configurations =
        bench->add_option("-c,--configurations", options->configurations, "Configurations to measure")
            ->check(configurationValidator());
    CLI::Option* draws =
        bench->add_option("-n,--draws", options->draws, "Draws per frame")->check(CLI::Range(1u, 1000000u));
    CLI::Option* minTime = bench->add_option("--min-time", options->minTime, "Minimum seconds per benchmark")
                               ->check(CLI::Range(0.01, 60.0));
    bench->add_option(
        "--json", options->json,
        "Also write the figures to this file: {\"draws\": [{configuration, draws, rhiNsPerDraw, "
        "rawNsPerDraw, rhiOverRaw, validatedNsPerDraw, validatedOverRhi}], \"shadows\": [{configuration, scenario, atlasPassMs, "
        "otherAtlasPassMs, litPassMs, frameMs, casterDraws, ...}]}; with --scene {\"scene\": "
        "[{configuration, frames, frameMs, frameMsMin, frameMsMax, passes: {depth, directionalAtlas, "
        "otherAtlas, screenSpaceShadows, lit, resolve, reference}, litOverReference, ...}]}");

    // Any scene's frames: the options of `render`, each meaningful only with --scene.
    addSceneOptions(*bench, scene->scene);
    CLI::Option* sceneOption = bench->get_option("--scene");
    sceneOption->excludes(suites)->excludes(configurations)->excludes(draws)->excludes(minTime);
    // bench takes several light counts in one run: its own --lights replaces the scene options' single count.
    bench->remove_option(bench->get_option("--lights"));
    bench
        ->add_option("--lights", scene->lightCounts,
                     "With --scene: keep the scene's first N local lights (its spot lights, then its point lights); "
                     "several counts, comma-separated, measure each in turn")
        ->check(CLI::Range(0u, 1000000u))
        ->delimiter(',');
    for (const char* name :
         {"--lights", "--camera", "--light", "--ambient", "--environment", "--environment-intensity",
          "--environment-rotation", "--settings", "--size", "--prepass", "--instancing", "--msaa", "--shadow-path"})
        bench->get_option(name)->needs(sceneOption);
    bench
        ->add_option("-b,--backend", scene->backends,
                     "With --scene: configurations to measure, comma-separated, or all")
        ->check(backendValidator())
        ->delimiter(',')
        ->needs(sceneOption)
        ->capture_default_str();
    bench->add_option("--frames", scene->frames, "With --scene: frames measured per configuration")
        ->check(CLI::Range(1u, 100000u))
        ->needs(sceneOption)
        ->capture_default_str();
    bench->add_option("--warmup", scene->warmup, "With --scene: frames drawn first and not measured")
        ->check(CLI::Range(0u, 1000u))
        ->needs(sceneOption)
        ->capture_default_str();
    addValidateFlag(*bench, scene->validate);
    bench->callback([options, scene, bench] {
        installInterruptHandler();
        if (bench->count("--scene") == 0) {
            runBenchmarks(*options);
            return;
        }
        const nlohmann::json json = runSceneBench(*scene);
        stopIfInterrupted();
        if (!options->json.empty()) {
            parity::writeTextFile(options->json, json.dump(2) + "\n");
            fmt::print("wrote {}\n", options->json);
        }
    });
}

} // namespace penumbra::apps
