#include "BackendOptions.hpp"
#include "CallBench.hpp"
#include "Commands.hpp"
#include "CullingComparison.hpp"
#include "Interrupt.hpp"
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

std::vector<std::string> allSuites()
{
    std::vector<std::string> suites = CallBench::suites();
    suites.insert(suites.end(), {"shadows", "soft"});
    return suites;
}

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

void runBenchmarks(const BenchOptions& options)
{
    std::vector<std::string> callSuites;
    for (const std::string& suite : CallBench::suites())
        if (wants(options, suite))
            callSuites.push_back(suite);
    const CallBench callBench(callSuites, options.configurations, options.draws, options.minTime);

    std::optional<ShadowBench> shadowBench;
    if (wants(options, "shadows"))
        shadowBench.emplace(options.configurations, options.minTime);

    std::optional<SoftShadowBench> softBench;
    if (wants(options, "soft"))
        softBench.emplace(options.configurations, options.minTime);
    CollectingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    nlohmann::json json = callBench.toJson(reporter.seconds);
    json["shadows"] = nlohmann::json::array();
    json["soft"] = nlohmann::json::array();
    if (shadowBench) {
        shadowBench->printSummary();
        json["shadows"] = shadowBench->toJson();
    }
    if (softBench) {
        softBench->printSummary();
        json["soft"] = softBench->toJson();
    }
    callBench.printSummary(reporter.seconds);
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
        "bench", "Time N small draws, indirect draws or dispatches per frame through the RHI (without and with its "
                 "validation layer) and through hand-written raw API code, and the shadow passes of the test scene; "
                 "or, with --scene, every pass of any scene's frames");
    CLI::Option* suites =
        bench
            ->add_option("-s,--suites", options->suites,
                         "draws, indirect (drawIndexedIndirect), dispatches, shadows, soft (the soft-shadow filters' "
                         "lit pass)")
            ->check(CLI::IsMember(allSuites()))
            ->delimiter(',');
    CLI::Option* configurations =
        bench->add_option("-c,--configurations", options->configurations, "Configurations to measure")
            ->check(configurationValidator());
    CLI::Option* draws = bench->add_option("-n,--draws", options->draws, "Draws (or dispatches) per frame")
                             ->check(CLI::Range(1u, 1000000u));
    CLI::Option* minTime = bench->add_option("--min-time", options->minTime, "Minimum seconds per benchmark")
                               ->check(CLI::Range(0.01, 60.0));
    bench->add_option(
        "--json", options->json,
        "Also write the figures to this file: {\"draws\": [{configuration, draws, rhiNsPerDraw, "
        "rawNsPerDraw, rhiOverRaw, validatedNsPerDraw, validatedOverRhi}], \"indirect\": [the same], "
        "\"dispatches\": [{configuration, dispatches, rhiNsPerDispatch, rawNsPerDispatch, rhiOverRaw, "
        "validatedNsPerDispatch, validatedOverRhi}], \"shadows\": [{configuration, scenario, atlasPassMs, "
        "otherAtlasPassMs, litPassMs, frameMs, casterDraws, ...}]}; with --scene {\"scene\": "
        "[{configuration, frames, frameMs, frameMsMin, frameMsMax, passes: {depth, directionalAtlas, "
        "otherAtlas, screenSpaceShadows, lit, resolve, reference, staticAtlas, contactShadows, depthFit, "
        "casterCulling, lightClusters, viewCulling}, culling, clusterBuild, cpuFrameMs, litOverReference, ...}]}");

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
    bench
        ->add_option("--frames", scene->frames,
                     "With --scene: frames measured per configuration (with --time or --animation, each frame 1/60 s "
                     "further into the animation, looping)")
        ->check(CLI::Range(1u, 100000u))
        ->needs(sceneOption)
        ->capture_default_str();
    bench->add_option("--warmup", scene->warmup, "With --scene: frames drawn first and not measured")
        ->check(CLI::Range(0u, 1000u))
        ->needs(sceneOption)
        ->capture_default_str();
    auto compareCulling = std::make_shared<bool>(false);
    bench
        ->add_flag(
            "--compare-culling", *compareCulling,
            "With --scene: alternate GPU-culled and CPU-culled frames (--culling gpu and cpu) in one process per "
            "configuration and print the GPU-culled frame over the CPU path's; --frames counts the pairs. "
            "JSON: {\"cullingComparison\": [{configuration, gpuFrameMs, cpuPathFrameMs, gpuOverCpu, "
            "pairedGpuOverCpu, gpuCpuFrameMs, cpuPathCpuFrameMs, ...}]}")
        ->needs(sceneOption)
        ->excludes(bench->get_option("--culling"));
    addValidateFlag(*bench, scene->validate);
    bench->callback([options, scene, bench, compareCulling] {
        installInterruptHandler();
        if (bench->count("--scene") == 0) {
            runBenchmarks(*options);
            return;
        }
        const nlohmann::json json = *compareCulling ? runCullingComparison(*scene) : runSceneBench(*scene);
        stopIfInterrupted();
        if (!options->json.empty()) {
            parity::writeTextFile(options->json, json.dump(2) + "\n");
            fmt::print("wrote {}\n", options->json);
        }
    });
}

} // namespace penumbra::apps
