// DeviceDesc::pipelineCache through the real drivers: a second device (as a second process would, the shader memo
// forgotten) reads SPIR-V and the driver's pipelines back instead of compiling, draws the same picture, and refuses
// a driver entry that is damaged or made for another device, with a note.
#include "GpuTesting.hpp"
#include "ScratchFolder.hpp"
#include "TestPattern.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/PipelineCache.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<rhi::Device> deviceWithCache(const std::shared_ptr<rhi::PipelineCache>& cache)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration());
    desc.validation = true;
    desc.pipelineCache = cache;
    return createDevice(desc);
}

// The test pattern drawn by a device of this configuration using `folder`'s cache, as a fresh process would.
struct CachedRun {
    rhi::Image picture;
    std::shared_ptr<rhi::PipelineCache> cache;
    bool pipelineBinaries = false;
    std::string backend;
};

CachedRun drawWithCache(const fs::path& folder)
{
    rhi::forgetCompiledShaders();
    CachedRun run{.cache = std::make_shared<rhi::PipelineCache>(folder)};
    {
        const std::unique_ptr<rhi::Device> device = deviceWithCache(run.cache);
        pattern::PatternRenderer renderer(*device, {.width = 32, .height = 32});
        renderer.render(pattern::testPattern());
        run.picture = renderer.color();
        run.pipelineBinaries = device->capabilities().pipelineBinaries;
        run.backend = device->desc().backend;
        expectNoDebugMessages(*device);
    } // the Vulkan cache is stored as the device goes
    return run;
}

std::string contents(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The only entry of `kind` in `folder`.
fs::path entryOf(const fs::path& folder, const std::string& kind)
{
    for (const fs::directory_entry& e : fs::directory_iterator(folder))
        if (e.path().filename().string().starts_with(kind + "-"))
            return e.path();
    return {};
}

// Stores the entry at `file` again with its payload changed by `change`, checksum and all: a file the cache's own
// checks accept, so that what refuses it is the check of the driver's data.
void restoreChanged(const fs::path& folder, const fs::path& file, const std::string& kind,
                    const std::function<void(std::string&)>& change)
{
    const std::string bytes = contents(file);
    std::uint32_t identityBytes = 0;
    std::uint32_t keyBytes = 0;
    std::memcpy(&identityBytes, bytes.data() + 12, 4); // the header's layout: rhi/src/PipelineCache.cpp
    std::memcpy(&keyBytes, bytes.data() + 16, 4);
    const std::string identity = bytes.substr(40, identityBytes);
    const std::string key = bytes.substr(40 + identityBytes, keyBytes);
    std::string payload = bytes.substr(40 + identityBytes + keyBytes);
    change(payload);
    rhi::PipelineCache(folder).store(kind, identity, key, payload, 0.0);
}

TEST(PipelineCacheTest, SecondDeviceLoadsWhatTheFirstCompiledAndDrawsTheSamePicture)
{
    const fs::path folder = scratchFolder("pipeline-cache-gpu", configuration() + "-second-device");
    const CachedRun cold = drawWithCache(folder);
    EXPECT_GT(cold.cache->counts()["spirv"].stored, 0u);
    EXPECT_EQ(cold.cache->counts()["spirv"].loaded, 0u);

    const CachedRun warm = drawWithCache(folder);
    const rhi::PipelineCacheCounts spirv = warm.cache->counts()["spirv"];
    EXPECT_EQ(spirv.missed, 0u) << warm.cache->summary();
    EXPECT_EQ(spirv.loaded, cold.cache->counts()["spirv"].stored);
    if (cold.pipelineBinaries) {
        EXPECT_EQ(warm.cache->counts()[warm.backend].loaded, 1u) << warm.cache->summary();
    } else {
        EXPECT_TRUE(entryOf(folder, warm.backend).empty()) << "no binary formats, yet an entry was written";
    }
    EXPECT_TRUE(warm.cache->notes().empty()) << warm.cache->summary();
    EXPECT_EQ(warm.picture.bytes, cold.picture.bytes);
}

TEST(PipelineCacheTest, DriverEntryForeignOrDamagedIsIgnored)
{
    const fs::path folder = scratchFolder("pipeline-cache-gpu", configuration() + "-foreign");
    const CachedRun cold = drawWithCache(folder);
    if (!cold.pipelineBinaries)
        GTEST_SKIP() << configuration() << ": the driver reports no program binary formats";
    const fs::path file = entryOf(folder, cold.backend);
    ASSERT_FALSE(file.empty());
    std::string why;
    if (cold.backend == "vulkan") {
        // VkPipelineCacheHeaderVersionOne's pipelineCacheUUID starts at byte 16 (Vulkan 1.3 section 10.7.4).
        restoreChanged(folder, file, "vulkan", [](std::string& data) { data[16] ^= 0x5a; });
        why = "foreign: pipeline cache data of vendor";
    } else {
        // A program binary the driver cannot take: its format kept, its bytes cut in half.
        restoreChanged(folder, file, cold.backend, [](std::string& data) { data.resize(4 + (data.size() - 4) / 2); });
        why = "the driver refused the program binary";
    }
    const CachedRun warm = drawWithCache(folder);
    EXPECT_EQ(warm.cache->counts()[warm.backend].ignored, 1u) << warm.cache->summary();
    ASSERT_EQ(warm.cache->notes().size(), 1u) << warm.cache->summary();
    EXPECT_NE(warm.cache->notes()[0].find(why), std::string::npos) << warm.cache->notes()[0];
    EXPECT_EQ(warm.picture.bytes, cold.picture.bytes);
}

} // namespace
} // namespace penumbra::testing
