// The pipeline cache's files (rhi::PipelineCache): what is stored loads back; a corrupt, truncated, foreign or
// unrelated file is ignored with a note and never returned; SPIR-V read back equals what glslang compiles.
#include "penumbra/rhi/PipelineCache.hpp"
#include "penumbra/rhi/Shader.hpp"

#include "ScratchFolder.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using penumbra::rhi::PipelineCache;

fs::path cacheScratch(const char* name) { return penumbra::testing::scratchFolder("pipeline-cache-tests", name); }

void overwrite(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

constexpr const char* kIdentity = "driver A on device 1";
constexpr const char* kKey = "the shaders' source";
constexpr const char* kPayload = "compiled bytes";

// A folder holding one stored entry, and that entry's file.
struct StoredEntry {
    fs::path folder;
    fs::path file;
};

StoredEntry storeOne(const char* test)
{
    const fs::path folder = cacheScratch(test);
    PipelineCache writer(folder);
    writer.store("spirv", kIdentity, kKey, kPayload, 1.0);
    return {folder, writer.entryPath("spirv", kIdentity, kKey)};
}

// What a second process opening the folder gets, with the single note it should leave.
void expectIgnored(const fs::path& folder, const std::string& why)
{
    PipelineCache reader(folder);
    EXPECT_EQ(reader.load("spirv", kIdentity, kKey), std::nullopt);
    ASSERT_EQ(reader.notes().size(), 1u);
    EXPECT_NE(reader.notes()[0].find(why), std::string::npos) << reader.notes()[0];
    EXPECT_EQ(reader.counts()["spirv"].ignored, 1u);
    EXPECT_EQ(reader.counts()["spirv"].loaded, 0u);
}

TEST(PipelineCache, StoredEntryLoadsBackInAnotherInstance)
{
    const StoredEntry stored = storeOne("loads-back");
    PipelineCache reader(stored.folder);
    EXPECT_EQ(reader.load("spirv", kIdentity, kKey), std::string(kPayload));
    EXPECT_EQ(reader.load("spirv", kIdentity, "another key"), std::nullopt);
    EXPECT_EQ(reader.counts()["spirv"].loaded, 1u);
    EXPECT_EQ(reader.counts()["spirv"].missed, 1u);
    EXPECT_TRUE(reader.notes().empty());
    // Written through a temporary file and a rename: nothing else is left in the folder.
    EXPECT_EQ(std::distance(fs::directory_iterator(stored.folder), fs::directory_iterator()), 1);
}

TEST(PipelineCache, CorruptEntryIsIgnored)
{
    const StoredEntry stored = storeOne("corrupt");
    std::string bytes = penumbra::testing::fileContents(stored.file);
    bytes.back() ^= 0x20; // one bit of the payload
    overwrite(stored.file, bytes);
    expectIgnored(stored.folder, "corrupt: the checksum does not match");
}

TEST(PipelineCache, TruncatedEntryIsIgnored)
{
    const StoredEntry stored = storeOne("truncated");
    const std::string bytes = penumbra::testing::fileContents(stored.file);
    overwrite(stored.file, bytes.substr(0, bytes.size() - 3));
    expectIgnored(stored.folder, "truncated");
    overwrite(stored.file, bytes.substr(0, 10));
    expectIgnored(stored.folder, "truncated: 10 bytes");
}

TEST(PipelineCache, ForeignEntryIsIgnored)
{
    const StoredEntry stored = storeOne("foreign");
    // Another driver's entry under this driver's name: what a copied or shared cache folder can hold.
    const fs::path ours = stored.file;
    PipelineCache writer(stored.folder);
    writer.store("spirv", "driver B on device 2", kKey, kPayload, 1.0);
    fs::rename(writer.entryPath("spirv", "driver B on device 2", kKey), ours);
    expectIgnored(stored.folder, "foreign: written for 'driver B on device 2'");
}

TEST(PipelineCache, FileOfAnotherKindIsIgnored)
{
    const StoredEntry stored = storeOne("not-a-cache-file");
    overwrite(stored.file, std::string(64, 'x'));
    expectIgnored(stored.folder, "not a Penumbra cache file");
}

TEST(PipelineCache, UnwritableFolderIsANoteNotAnError)
{
    const fs::path folder = cacheScratch("unwritable");
    overwrite(folder / "file", "a file where the cache's folder should be");
    PipelineCache cache(folder / "file");
    EXPECT_NO_THROW(cache.store("spirv", kIdentity, kKey, kPayload, 1.0));
    ASSERT_EQ(cache.notes().size(), 1u);
    EXPECT_NE(cache.notes()[0].find("not stored"), std::string::npos) << cache.notes()[0];
    EXPECT_EQ(cache.counts()["spirv"].stored, 0u);
}

TEST(PipelineCache, DefaultFolderFollowsXdgCacheHome)
{
    const char* saved = std::getenv("XDG_CACHE_HOME");
    const std::string restore = saved ? saved : "";
    ::setenv("XDG_CACHE_HOME", "/somewhere/cache", 1);
    EXPECT_EQ(penumbra::rhi::defaultPipelineCacheFolder(), fs::path("/somewhere/cache/penumbra"));
    // A relative path is invalid (XDG Base Directory Specification): $HOME/.cache instead.
    ::setenv("XDG_CACHE_HOME", "relative", 1);
    const char* home = std::getenv("HOME");
    if (home && *home) {
        EXPECT_EQ(penumbra::rhi::defaultPipelineCacheFolder(), fs::path(home) / ".cache" / "penumbra");
    }
    if (saved)
        ::setenv("XDG_CACHE_HOME", restore.c_str(), 1);
    else
        ::unsetenv("XDG_CACHE_HOME");
}

// The SPIR-V entries through the shader compiler, the process's memo forgotten in between as a second process
// would start without it.
TEST(PipelineCache, SpirvReadBackEqualsCompiledAndDamagedSpirvIsCompiledAgain)
{
    const penumbra::rhi::ShaderSource source{
        .stage = penumbra::rhi::ShaderStage::Fragment,
        .source = "#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(0.25); }\n",
        .name = "PipelineCacheTest.frag"};
    const std::string preamble = "#define PIPELINE_CACHE_TEST 1\n";
    const fs::path folder = cacheScratch("spirv");

    penumbra::rhi::forgetCompiledShaders();
    PipelineCache first(folder);
    const penumbra::rhi::CompiledShader compiled = penumbra::rhi::compileShader(source, preamble, &first);
    EXPECT_EQ(first.counts()["spirv"].missed, 1u);
    EXPECT_EQ(first.counts()["spirv"].stored, 1u);

    penumbra::rhi::forgetCompiledShaders();
    PipelineCache second(folder);
    const penumbra::rhi::CompiledShader loaded = penumbra::rhi::compileShader(source, preamble, &second);
    EXPECT_EQ(second.counts()["spirv"].loaded, 1u);
    EXPECT_EQ(second.counts()["spirv"].missed, 0u);
    EXPECT_EQ(loaded.spirv, compiled.spirv);
    EXPECT_EQ(loaded.name, compiled.name);

    // A damaged entry is compiled anew, with a note, to the same SPIR-V.
    const fs::path file = fs::directory_iterator(folder)->path();
    std::string bytes = penumbra::testing::fileContents(file);
    bytes[bytes.size() / 2] ^= 0x01;
    overwrite(file, bytes);
    penumbra::rhi::forgetCompiledShaders();
    PipelineCache third(folder);
    EXPECT_EQ(penumbra::rhi::compileShader(source, preamble, &third).spirv, compiled.spirv);
    EXPECT_EQ(third.counts()["spirv"].ignored, 1u);
    EXPECT_EQ(third.notes().size(), 1u);
}

} // namespace
