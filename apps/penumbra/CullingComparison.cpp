#include "CullingComparison.hpp"

#include "BackendOptions.hpp"
#include "BenchSeries.hpp"
#include "Interrupt.hpp"
#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"

#include <chrono>
#include <fmt/format.h>
#include <string>

namespace penumbra::apps {
namespace {

// One culling mode's frames.
struct CulledFrames {
    render::FrameDesc frame;
    Series wallMs;
    Series cpuFrameMs; // planning + recording

    // Renders one frame; keeps its figures where `measured`.
    double draw(render::SceneRenderer& renderer, const scene::Scene& scene, bool measured)
    {
        const auto start = std::chrono::steady_clock::now();
        const render::FrameStats stats = renderer.render(scene.camera, frame);
        const double ms = 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (measured) {
            wallMs.values.push_back(ms);
            cpuFrameMs.values.push_back(stats.planningMs + stats.recordingMs);
        }
        return ms;
    }
};

struct Comparison {
    std::string configuration;
    CulledFrames gpu, cpu;
    Series pairRatios; // each pair's GPU-culled frame over its CPU-culled one
};

Comparison compare(const std::string& configuration, const scene::Scene& scene, const render::FrameDesc& frame,
                   const SceneBenchOptions& options)
{
    auto device = createDevice(toolDeviceDesc(configuration, options.validate));
    Comparison c{configuration, {frame, {}, {}}, {frame, {}, {}}, {}};
    c.gpu.frame.shadows.culling = shadows::CasterCullingMode::Gpu;
    c.cpu.frame.shadows.culling = shadows::CasterCullingMode::Cpu;
    render::SceneRenderer gpuRenderer(*device, scene), cpuRenderer(*device, scene);
    const std::uint32_t pairs = options.warmup + options.frames;
    for (std::uint32_t i = 0; i < pairs; ++i) {
        stopIfInterrupted();
        const bool measured = i >= options.warmup;
        double gpu = 0.0, cpu = 0.0;
        if (i % 2 == 0) {
            gpu = c.gpu.draw(gpuRenderer, scene, measured);
            cpu = c.cpu.draw(cpuRenderer, scene, measured);
        } else {
            cpu = c.cpu.draw(cpuRenderer, scene, measured);
            gpu = c.gpu.draw(gpuRenderer, scene, measured);
        }
        if (measured)
            c.pairRatios.values.push_back(gpu / cpu);
        showBenchProgress(configuration, 2 * (i + 1), 2 * pairs);
    }
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return c;
}

double ratio(double a, double b) { return b > 0.0 ? a / b : 0.0; }

} // namespace

nlohmann::json runCullingComparison(const SceneBenchOptions& options)
{
    const LoadedScene loaded = loadScene(options.scene);
    const render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    std::vector<Comparison> comparisons;
    for (const std::string& configuration : expandBackends(options.backends))
        comparisons.push_back(compare(configuration, loaded.scene, frame, options));

    fmt::print("\n{} at {}x{}: GPU-culled and CPU-culled frames alternated in one process, {} pairs after {} warm-up "
               "(medians of wall time per frame)\n",
               options.scene.scene, frame.width, frame.height, options.frames, options.warmup);
    fmt::print("{:<24} {:>13} {:>14} {:>10} {:>13} {:>13} {:>14}\n", "configuration", "gpu-culled ms", "cpu-culled ms",
               "gpu / cpu", "paired ratio", "gpu cpu ms", "cpu path cpu ms");
    nlohmann::json rows = nlohmann::json::array();
    for (const Comparison& c : comparisons) {
        const double gpu = c.gpu.wallMs.median(), cpu = c.cpu.wallMs.median();
        fmt::print("{:<24} {:>13.2f} {:>14.2f} {:>10.3f} {:>13.3f} {:>13.2f} {:>14.2f}\n", c.configuration, gpu, cpu,
                   ratio(gpu, cpu), c.pairRatios.median(), c.gpu.cpuFrameMs.median(), c.cpu.cpuFrameMs.median());
        rows.push_back({{"configuration", c.configuration},
                        {"scene", options.scene.scene},
                        {"width", frame.width},
                        {"height", frame.height},
                        {"frames", options.frames},
                        {"warmup", options.warmup},
                        {"gpuFrameMs", gpu},
                        {"cpuPathFrameMs", cpu},
                        {"gpuOverCpu", ratio(gpu, cpu)},
                        {"pairedGpuOverCpu", c.pairRatios.median()},
                        {"gpuCpuFrameMs", c.gpu.cpuFrameMs.median()},
                        {"cpuPathCpuFrameMs", c.cpu.cpuFrameMs.median()}});
    }
    return {{"cullingComparison", rows}};
}

} // namespace penumbra::apps
