// The RHI's threading contract (rhi::Device): a device and its objects belong to the thread that created it, and
// devices share no state, so devices of every configuration may run at once, one per thread. Also the two pieces
// of process-wide state under that contract: the shader compiler's memo and the ray caster's row threads.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"
#include "TestPattern.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Shader.hpp"
#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <thread>

namespace penumbra::testing {
namespace {

// What one configuration's thread produced: its lit image, or the reason it has none.
struct ThreadResult {
    std::string configuration;
    std::optional<rhi::Image> lit;
    std::string failure; // an error, or debug messages
    bool unsupported = false; // the driver refused the configuration
};

// The mixed scene (sun, spot and point shadows) on a validated device made, used and destroyed here.
ThreadResult renderOnThisThread(const std::string& configuration)
{
    ThreadResult result{.configuration = configuration};
    try {
        const std::unique_ptr<rhi::Device> device = createValidatedDevice(configuration);
        const scene::Scene scene = scenes::makeMixedLightsScene();
        result.lit = renderLit(*device, scene, litFrame(160, 90, true, 1));
        for (const std::string& message : device->debugMessages())
            result.failure += "\n  debug message: " + message;
    } catch (const rhi::UnsupportedError& e) {
        result.unsupported = true;
        result.failure = e.what();
    } catch (const std::exception& e) {
        result.failure = e.what();
    }
    return result;
}

TEST(DevicesOnThreads, EveryConfigurationRendersOnItsOwnThreadAsItDoesAlone)
{
    std::vector<ThreadResult> alone;
    for (const std::string& configuration : compiledConfigurations())
        alone.push_back(renderOnThisThread(configuration));

    std::vector<ThreadResult> together(alone.size());
    {
        std::vector<std::jthread> threads;
        for (std::size_t i = 0; i < alone.size(); ++i)
            threads.emplace_back([&, i] { together[i] = renderOnThisThread(alone[i].configuration); });
    }

    std::vector<SkippedConfiguration> skipped;
    for (std::size_t i = 0; i < alone.size(); ++i) {
        const std::string& name = alone[i].configuration;
        if (alone[i].unsupported) {
            skipped.push_back({name, alone[i].failure});
            continue;
        }
        ASSERT_TRUE(alone[i].lit && alone[i].failure.empty()) << name << " alone: " << alone[i].failure;
        ASSERT_TRUE(together[i].lit && together[i].failure.empty()) << name << " on a thread: " << together[i].failure;
        EXPECT_TRUE(together[i].lit->bytes == alone[i].lit->bytes)
            << name << ": the lit image rendered beside the other configurations differs from the one rendered alone";
    }
    reportSkipped(skipped);
}

// The memo of rhi::compileShader is shared by every device of the process: threads compiling the same and
// different sources at once get the SPIR-V a single thread gets.
TEST(DevicesOnThreads, ShaderCompilationFromManyThreadsGivesTheSameSpirv)
{
    const std::vector<rhi::ShaderSource> sources{pattern::patternVertexShader(), shaders::load("pattern.frag"),
                                                 shaders::load("mesh.frag"),
                                                 shaders::load("imgui.frag", {{"BINDING_TEXTURE", 1}})};
    std::vector<rhi::CompiledShader> expected;
    for (const rhi::ShaderSource& source : sources)
        expected.push_back(rhi::compileShader(source, ""));

    constexpr std::size_t kThreads = 8;
    std::vector<std::vector<rhi::CompiledShader>> compiled(kThreads);
    {
        std::vector<std::jthread> threads;
        for (std::size_t t = 0; t < kThreads; ++t)
            threads.emplace_back([&, t] {
                // A preamble no other test uses: these compiles miss the memo and race to fill it.
                for (std::size_t i = 0; i < sources.size(); ++i)
                    compiled[t].push_back(rhi::compileShader(sources[(i + t) % sources.size()],
                                                             fmt::format("#define PENUMBRA_THREAD_TEST {}\n", i % 2)));
            });
    }
    for (std::size_t t = 0; t < kThreads; ++t)
        for (std::size_t i = 0; i < sources.size(); ++i) {
            const std::size_t source = (i + t) % sources.size();
            const rhi::CompiledShader once =
                rhi::compileShader(sources[source], fmt::format("#define PENUMBRA_THREAD_TEST {}\n", i % 2));
            EXPECT_EQ(compiled[t][i].spirv, once.spirv) << sources[source].name << " on thread " << t;
            EXPECT_EQ(compiled[t][i].bindings.size(), expected[source].bindings.size()) << sources[source].name;
        }
}

// truth::traceGBuffer runs rows on every hardware thread and reports progress on the calling thread only.
TEST(DevicesOnThreads, RayCasterReportsProgressOnTheCallingThreadOnly)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    const truth::RayCaster rays(scene, truth::RayKind::Camera);
    const std::thread::id caller = std::this_thread::get_id();
    int elsewhere = 0;
    std::uint32_t finished = 0;
    const truth::CpuGBuffer gbuffer =
        truth::traceGBuffer(scene, rays, scene.camera, 64, 36, [&](std::uint32_t done, std::uint32_t rows) {
            // Counted without a lock on purpose: a call from another thread is a data race ThreadSanitizer reports.
            if (std::this_thread::get_id() != caller)
                ++elsewhere;
            finished = std::max(finished, done == rows ? done : 0u);
        });
    EXPECT_EQ(elsewhere, 0);
    EXPECT_EQ(finished, 36u);
    EXPECT_EQ(gbuffer.samples.size(), 64u * 36u);
}

} // namespace
} // namespace penumbra::testing
