#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace penumbra::testing {

// An empty folder <temp>/penumbra-<suite>/<name> for one test's files, emptied again at the next run.
inline std::filesystem::path scratchFolder(std::string_view suite, std::string_view name)
{
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("penumbra-" + std::string(suite)) / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// The bytes of a file; empty where it cannot be read.
inline std::string fileContents(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace penumbra::testing
