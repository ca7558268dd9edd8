#include "CallBench.hpp"

#include "DispatchScene.hpp"
#include "DrawScene.hpp"
#include "RawFrames.hpp"

#include "penumbra/backends/CreateDevice.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <functional>

namespace penumbra::apps {

struct CallBench::Case {
    std::string suite;
    std::string configuration;
    std::uint32_t calls;
    std::string rhiName, validatedName, rawName;
};

// What the benchmarks use, alive until every benchmark has run.
struct CallBench::Objects {
    std::vector<std::unique_ptr<rhi::Device>> devices;
    std::vector<std::unique_ptr<DrawScene>> drawScenes;
    std::vector<std::unique_ptr<DispatchScene>> dispatchScenes;
    std::vector<std::unique_ptr<rhi::CommandList>> lists;
    std::vector<std::unique_ptr<RawFrame>> raws;
};

namespace {

void registerFrame(const std::string& name, double minTime, std::function<void()> frame)
{
    benchmark::RegisterBenchmark(name.c_str(),
                                 [frame = std::move(frame)](benchmark::State& state) {
                                     for (auto _ : state)
                                         frame();
                                 })
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond)
        ->MinTime(minTime);
}

// A scene of `calls` calls on `device`, recorded by `record` and submitted each iteration of benchmark `name`.
template <class Scene, class Record>
const Scene& registerRhiFrame(std::vector<std::unique_ptr<Scene>>& scenes,
                              std::vector<std::unique_ptr<rhi::CommandList>>& lists, const std::string& name,
                              rhi::Device& device, std::uint32_t calls, double minTime, Record record)
{
    const Scene& scene = *scenes.emplace_back(std::make_unique<Scene>(device, calls));
    rhi::CommandList& commands = *lists.emplace_back(device.createCommandList());
    registerFrame(name, minTime, [&device, &scene, &commands, record] {
        record(scene, commands);
        device.submit(commands);
    });
    return scene;
}

// Each suite and the JSON names of its figures (draws: "draws", "rhiNsPerDraw", ...).
struct SuiteNames {
    const char* suite;
    const char* count;
    const char* unit;
};
constexpr std::array<SuiteNames, 3> kSuites = {
    {{"draws", "draws", "Draw"}, {"indirect", "draws", "Draw"}, {"dispatches", "dispatches", "Dispatch"}}};

const SuiteNames& namesOf(const std::string& suite)
{
    return *std::find_if(kSuites.begin(), kSuites.end(), [&](const SuiteNames& n) { return suite == n.suite; });
}

} // namespace

const std::vector<std::string>& CallBench::suites()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const SuiteNames& n : kSuites)
            list.emplace_back(n.suite);
        return list;
    }();
    return names;
}

CallBench::CallBench(const std::vector<std::string>& suites, const std::vector<std::string>& configurations,
                     const std::vector<std::uint32_t>& calls, double minTime)
    : objects_(std::make_unique<Objects>())
{
    Objects& o = *objects_;
    for (const std::string& configuration : suites.empty() ? std::vector<std::string>{} : configurations) {
        rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
        desc.validation = false; // timing the driver, not the API's validation layer
        desc.validateUsage = false;
        rhi::Device& device = *o.devices.emplace_back(createDevice(desc));
        // The same calls through the RHI's own validation layer: its overhead is validated / rhi.
        desc.validateUsage = true;
        rhi::Device& validatedDevice = *o.devices.emplace_back(createDevice(desc));
        for (const std::string& suite : suites)
            for (std::uint32_t n : calls) {
                const auto name = [&](const char* path) {
                    return fmt::format("{}/{}/{}/{}", suite, configuration, path, n);
                };
                const Case& c =
                    cases_.emplace_back(Case{suite, configuration, n, name("rhi"), name("rhi-validated"), name("raw")});
                std::unique_ptr<RawFrame> raw;
                if (suite == "dispatches") {
                    const auto record = [](const DispatchScene& s, rhi::CommandList& l) { s.recordRhi(l); };
                    const DispatchScene& scene =
                        registerRhiFrame(o.dispatchScenes, o.lists, c.rhiName, device, n, minTime, record);
                    registerRhiFrame(o.dispatchScenes, o.lists, c.validatedName, validatedDevice, n, minTime, record);
                    raw = createRawDispatches(device, scene);
                } else {
                    const DrawCall call = suite == "indirect" ? DrawCall::Indirect : DrawCall::Direct;
                    const auto record = [call](const DrawScene& s, rhi::CommandList& l) { s.recordRhi(l, call); };
                    const DrawScene& scene =
                        registerRhiFrame(o.drawScenes, o.lists, c.rhiName, device, n, minTime, record);
                    registerRhiFrame(o.drawScenes, o.lists, c.validatedName, validatedDevice, n, minTime, record);
                    raw = createRawDraws(device, scene, call);
                }
                RawFrame& rawFrame = *o.raws.emplace_back(std::move(raw));
                registerFrame(c.rawName, minTime, [&rawFrame] { rawFrame.frame(); });
            }
    }
}

CallBench::~CallBench() = default;

void CallBench::printSummary(const std::map<std::string, double>& seconds) const
{
    if (cases_.empty())
        return;
    fmt::print("\n{:<11} {:<24} {:>7} {:>12} {:>12} {:>10} {:>12} {:>10}\n", "suite", "configuration", "calls",
               "rhi ns/call", "raw ns/call", "rhi / raw", "validated", "val. / rhi");
    for (const Case& c : cases_) {
        const double rhi = seconds.at(c.rhiName) * 1e9 / c.calls;
        const double validated = seconds.at(c.validatedName) * 1e9 / c.calls;
        const double raw = seconds.at(c.rawName) * 1e9 / c.calls;
        fmt::print("{:<11} {:<24} {:>7} {:>12.1f} {:>12.1f} {:>10.3f} {:>12.1f} {:>10.3f}\n", c.suite, c.configuration,
                   c.calls, rhi, raw, rhi / raw, validated, validated / rhi);
    }
}

nlohmann::json CallBench::toJson(const std::map<std::string, double>& seconds) const
{
    nlohmann::json json = nlohmann::json::object();
    for (const std::string& suite : suites())
        json[suite] = nlohmann::json::array();
    for (const Case& c : cases_) {
        const SuiteNames& names = namesOf(c.suite);
        const std::string unit = names.unit;
        const double rhi = seconds.at(c.rhiName) * 1e9 / c.calls;
        const double validated = seconds.at(c.validatedName) * 1e9 / c.calls;
        const double raw = seconds.at(c.rawName) * 1e9 / c.calls;
        json[c.suite].push_back({{"configuration", c.configuration},
                                 {names.count, c.calls},
                                 {"rhiNsPer" + unit, rhi},
                                 {"rawNsPer" + unit, raw},
                                 {"rhiOverRaw", rhi / raw},
                                 {"validatedNsPer" + unit, validated},
                                 {"validatedOverRhi", validated / rhi}});
    }
    return json;
}

} // namespace penumbra::apps
