// penumbra soak: many frames of one scene while its settings, lights, size and the scene itself change the way a
// viewer user changes them; fails when resident memory or live RHI objects grow after the warm-up, or when the
// validation layer or the GL debug output says anything.
#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "Interrupt.hpp"
#include "SceneOptions.hpp"
#include "SoakChanges.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/LiveObjects.hpp"

#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>
#include <tuple>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace penumbra::apps {
namespace {

struct SoakOptions {
    SceneOptions scene;
    std::string backend = "vulkan";
    std::uint32_t frames = 1000;
    std::uint32_t seed = 1;
    std::uint32_t warmup = 100;
    std::uint32_t checkEvery = 50;
    double memoryToleranceMiB = 16.0;
    std::uint32_t objectTolerance = 0;
    std::string json;
    std::string apiValidation = "on";
};

// What is measured at a checkpoint: a frame of the scene's own lights and the starting frame, so that every
// checkpoint draws the same thing and holds the same objects unless something leaks.
struct Sample {
    std::uint32_t frame = 0;
    std::uint64_t residentBytes = 0;
    rhi::LiveObjectCounts objects{};
};

// Resident set size: the second field of /proc/self/statm, in pages (proc(5)).
std::uint64_t residentBytes()
{
    std::ifstream statm("/proc/self/statm");
    std::uint64_t size = 0, resident = 0;
    if (!(statm >> size >> resident))
        throw rhi::Error("soak: cannot read /proc/self/statm");
    return resident * std::uint64_t(::sysconf(_SC_PAGESIZE));
}

using Lights =
    std::tuple<std::vector<scene::DirectionalLight>, std::vector<scene::SpotLight>, std::vector<scene::PointLight>>;

Lights lightsOf(const scene::Scene& scene) { return {scene.lights, scene.spotLights, scene.pointLights}; }

void setLights(scene::Scene& scene, const Lights& lights)
{
    std::tie(scene.lights, scene.spotLights, scene.pointLights) = lights;
}

double mib(std::uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

nlohmann::json objectsJson(const rhi::LiveObjectCounts& counts)
{
    nlohmann::json json = nlohmann::json::object();
    for (std::size_t k = 0; k < rhi::kObjectKindCount; ++k)
        json[std::string(rhi::objectKindName(rhi::ObjectKind(k)))] = counts[k];
    return json;
}

// The highest counts and resident memory of the checkpoints in the warm-up are the reference.
Sample warmupPeak(const std::vector<Sample>& samples, std::uint32_t warmup)
{
    Sample peak;
    for (const Sample& s : samples) {
        if (s.frame >= warmup)
            break;
        peak.frame = s.frame;
        peak.residentBytes = std::max(peak.residentBytes, s.residentBytes);
        for (std::size_t k = 0; k < rhi::kObjectKindCount; ++k)
            peak.objects[k] = std::max(peak.objects[k], s.objects[k]);
    }
    return peak;
}

// Growth is what the last quarter of the checkpoints after the warm-up (at least the last one) holds at its lowest:
// more objects of a kind than the warm-up's peak, or more resident memory than the tolerance (the allocator's own
// fragmentation) above it. Objects a component keeps from an earlier setting until it next changes (a pipeline of
// another depth format) come and go between checkpoints; a leak raises the floor and keeps it raised.
void judge(const std::vector<Sample>& samples, const SoakOptions& options)
{
    const Sample peak = warmupPeak(samples, options.warmup);
    const auto afterWarmup =
        std::find_if(samples.begin(), samples.end(), [&](const Sample& s) { return s.frame >= options.warmup; });
    const auto judged = samples.end() - std::max<std::ptrdiff_t>(1, (samples.end() - afterWarmup) / 4);
    Sample floor = *judged;
    for (auto s = judged; s != samples.end(); ++s) {
        floor.residentBytes = std::min(floor.residentBytes, s->residentBytes);
        for (std::size_t k = 0; k < rhi::kObjectKindCount; ++k)
            floor.objects[k] = std::min(floor.objects[k], s->objects[k]);
    }
    for (std::size_t k = 0; k < rhi::kObjectKindCount; ++k)
        if (floor.objects[k] > peak.objects[k] + options.objectTolerance)
            throw rhi::Error(fmt::format("soak: live {} objects stay above the warm-up's {} from frame {} on (at least "
                                         "{})",
                                         rhi::objectKindName(rhi::ObjectKind(k)), peak.objects[k], judged->frame,
                                         floor.objects[k]));
    if (mib(floor.residentBytes) > mib(peak.residentBytes) + options.memoryToleranceMiB)
        throw rhi::Error(fmt::format("soak: resident memory stays above the warm-up's {:.1f} MiB by more than "
                                     "--memory-tolerance {} MiB from frame {} on (at least {:.1f} MiB)",
                                     mib(peak.residentBytes), options.memoryToleranceMiB, judged->frame,
                                     mib(floor.residentBytes)));
}

void printSample(const char* label, const Sample& s)
{
    std::string objects;
    for (std::size_t k = 0; k < rhi::kObjectKindCount; ++k)
        objects += fmt::format(" {} {}", rhi::objectKindName(rhi::ObjectKind(k)), s.objects[k]);
    fmt::print("  {} (frame {}): resident {:.1f} MiB;{}\n", label, s.frame, mib(s.residentBytes), objects);
}

void soak(const SoakOptions& options)
{
    if (options.warmup >= options.frames)
        throw rhi::Error(
            fmt::format("--warmup: {} leaves none of the {} --frames to judge", options.warmup, options.frames));
    const LoadedScene loaded = loadScene(options.scene);
    const render::FrameDesc start = frameDesc(options.scene, loaded.scene);
    rhi::DeviceDesc desc = toolDeviceDesc(options.backend, true);
    desc.validation = options.apiValidation == "on";
    auto device = createDevice(desc);
    auto scene = std::make_unique<scene::Scene>(loaded.scene);
    auto renderer = std::make_unique<render::SceneRenderer>(*device, *scene);
    render::FrameDesc frame = start;
    std::mt19937 random(options.seed);
    std::array<std::uint32_t, kSoakChangeCount> applied{};
    std::vector<Sample> samples;

    for (std::uint32_t i = 0; i < options.frames; ++i) {
        stopIfInterrupted();
        const bool checkpoint = (i + 1) % options.checkEvery == 0 || i + 1 == options.frames;
        // A checkpoint draws the starting lights and frame, then the walk goes on from where it was.
        std::optional<std::pair<Lights, render::FrameDesc>> held;
        if (checkpoint) {
            held.emplace(lightsOf(*scene), frame);
            setLights(*scene, lightsOf(loaded.scene));
            frame = start;
        } else if (std::bernoulli_distribution(0.5)(random)) {
            const SoakChange change = drawSoakChange(random);
            ++applied[std::size_t(change)];
            if (change == SoakChange::SceneReload) {
                renderer.reset();
                scene = std::make_unique<scene::Scene>(loadScene(options.scene).scene);
                renderer = std::make_unique<render::SceneRenderer>(*device, *scene);
            } else {
                SoakState state{*scene, frame, start, scene->worldBounds()};
                applySoakChange(change, random, state);
            }
        }
        renderer->render(scene->camera, frame);
        if (const auto messages = device->debugMessages(); !messages.empty())
            throw rhi::Error(fmt::format("soak: {} validation / debug message(s) by frame {}, first: {}",
                                         messages.size(), i, messages[0]));
        if (held) {
            setLights(*scene, held->first);
            frame = held->second;
        }
        if (checkpoint) {
            samples.push_back({i, residentBytes(), rhi::liveObjectCounts()});
            fmt::print(stderr, "\rsoak {}: frame {}/{}, resident {:.1f} MiB", options.backend, i + 1, options.frames,
                       mib(samples.back().residentBytes));
            std::fflush(stderr);
        }
    }
    fmt::print(stderr, "\n");

    fmt::print("soak {} on {}: {} frames, seed {}, {} changes, 0 validation / debug messages (API validation {})\n",
               options.scene.scene, options.backend, options.frames, options.seed,
               std::accumulate(applied.begin(), applied.end(), 0u), options.apiValidation);
    printSample("first checkpoint", samples.front());
    printSample("warm-up peak", warmupPeak(samples, options.warmup));
    printSample("last checkpoint", samples.back());
    if (!options.json.empty()) {
        nlohmann::json json = {{"scene", options.scene.scene},
                               {"configuration", options.backend},
                               {"frames", options.frames},
                               {"seed", options.seed},
                               {"warmup", options.warmup},
                               {"changes", nlohmann::json::object()},
                               {"checkpoints", nlohmann::json::array()}};
        for (std::size_t c = 0; c < kSoakChangeCount; ++c)
            json["changes"][std::string(soakChangeName(SoakChange(c)))] = applied[c];
        for (const Sample& s : samples)
            json["checkpoints"].push_back(
                {{"frame", s.frame}, {"residentMiB", mib(s.residentBytes)}, {"objects", objectsJson(s.objects)}});
        stopIfInterrupted();
        parity::writeTextFile(options.json, json.dump(2) + "\n");
        fmt::print("  wrote {}\n", options.json);
    }
    judge(samples, options);
    fmt::print("soak: no growth past the warm-up of {} frames (the last quarter of the checkpoints: live objects "
               "within the warm-up's peak, resident memory within {} MiB of it)\n",
               options.warmup, options.memoryToleranceMiB);
}

} // namespace

void addSoakCommand(CLI::App& app)
{
    auto options = std::make_shared<SoakOptions>();
    CLI::App* command = app.add_subcommand(
        "soak", "Render many frames while settings, lights, size and the scene change at random (seeded), as a viewer "
                "user would; fails when resident memory or live RHI objects grow after the warm-up, or on any "
                "validation / debug message (the Vulkan validation layer and GL debug output are on unless "
                "--api-validation off)");
    addSceneOptions(*command, options->scene);
    command->add_option("-b,--backend", options->backend, "One configuration name (vulkan, opengl-reversed, ...)")
        ->check(configurationValidator())
        ->capture_default_str();
    command->add_option("-n,--frames", options->frames, "Frames to render")
        ->check(CLI::Range(2u, 10'000'000u))
        ->capture_default_str();
    command->add_option("--seed", options->seed, "Seed of the changes")->capture_default_str();
    command
        ->add_option("--warmup", options->warmup,
                     "Frames before the reference checkpoint (caches fill, the "
                     "allocator settles)")
        ->capture_default_str();
    command
        ->add_option("--check-every", options->checkEvery,
                     "Frames between checkpoints (the starting lights and frame, measured)")
        ->check(CLI::Range(1u, 100'000u))
        ->capture_default_str();
    command
        ->add_option("--memory-tolerance", options->memoryToleranceMiB,
                     "MiB of resident memory a checkpoint may hold above the reference one")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    command
        ->add_option("--api-validation", options->apiValidation,
                     "on: the Vulkan validation layer and GL debug output (the RHI's own validation is always on); "
                     "off measures the driver alone, without the layer's own bookkeeping")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    command
        ->add_option("--object-tolerance", options->objectTolerance,
                     "Live objects of a kind the last checkpoints may hold above the warm-up's peak")
        ->capture_default_str();
    command->add_option("--json", options->json, "Write the checkpoints and the changes applied as JSON");
    command->callback([options] {
        installInterruptHandler();
        soak(*options);
    });
}

} // namespace penumbra::apps
