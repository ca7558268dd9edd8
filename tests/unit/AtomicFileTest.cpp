#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include "ScratchFolder.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using penumbra::rhi::writeFileAtomically;

fs::path atomicScratch(const char* name) { return penumbra::testing::scratchFolder("atomic-file-tests", name); }

std::size_t entries(const fs::path& folder)
{
    return std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

std::string failureOf(const fs::path& path)
{
    try {
        writeFileAtomically(path, "bytes");
    } catch (const penumbra::rhi::Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(AtomicFile, WritesAndReplacesLeavingOnlyTheFile)
{
    const fs::path folder = atomicScratch("replace");
    writeFileAtomically(folder / "a.json", "first");
    writeFileAtomically(folder / "a.json", "second, longer");
    EXPECT_EQ(penumbra::testing::fileContents(folder / "a.json"), "second, longer");
    EXPECT_EQ(entries(folder), 1u);
    EXPECT_STREQ(penumbra::rhi::temporaryFileInProgress(), "");
}

TEST(AtomicFile, CreatesParentFolders)
{
    const fs::path folder = atomicScratch("parents");
    writeFileAtomically(folder / "x" / "y" / "z.txt", "deep");
    EXPECT_EQ(penumbra::testing::fileContents(folder / "x" / "y" / "z.txt"), "deep");
}

TEST(AtomicFile, FullDiskIsANamedError)
{
    EXPECT_EQ(failureOf("/dev/full"), "cannot write /dev/full: No space left on device");
    EXPECT_TRUE(fs::is_character_file("/dev/full")) << "the device was replaced by a file";
}

TEST(AtomicFile, FolderThatCannotBeMadeIsANamedError)
{
    const fs::path folder = atomicScratch("not-a-folder");
    writeFileAtomically(folder / "file", "a file, not a folder");
    EXPECT_EQ(failureOf(folder / "file" / "sub" / "out.png"),
              "cannot write " + (folder / "file" / "sub" / "out.png").string() + ": cannot create the folder " +
                  (folder / "file" / "sub").string() + ": Not a directory");
    EXPECT_EQ(entries(folder), 1u);
}

TEST(AtomicFile, FolderInThePlaceOfTheFileIsANamedError)
{
    const fs::path folder = atomicScratch("folder-in-place");
    fs::create_directories(folder / "out.png");
    EXPECT_EQ(failureOf(folder / "out.png"), "cannot write " + (folder / "out.png").string() + ": it is a folder");
    EXPECT_EQ(entries(folder), 1u);
}

TEST(AtomicFile, UnwritableFolderLeavesNoTemporaryFile)
{
    EXPECT_EQ(failureOf("/proc/penumbra-atomic.json"),
              "cannot write /proc/penumbra-atomic.json: No such file or directory");
}

} // namespace
