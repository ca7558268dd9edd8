#pragma once
// The glTF loader tests' fixture: files written per test into a folder of their own, and their errors.
#include "GltfBuilder.hpp"

#include "penumbra/gltf/GltfLoader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace penumbra::scene {

using testing::Component;
using testing::GltfBuilder;

class GltfLoaderTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ =
            std::filesystem::temp_directory_path() / ("penumbra-gltf-" + std::to_string(::getpid())) / info->name();
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_.parent_path()); }

    std::filesystem::path write(const GltfBuilder& builder, const std::string& name = "scene.gltf")
    {
        const std::filesystem::path path = folder_ / name;
        if (path.extension() == ".glb")
            builder.writeGlb(path);
        else
            builder.writeGltf(path);
        return path;
    }

    // The GltfError's message for loading `path`, or "" when it loads.
    static std::string errorOf(const std::filesystem::path& path, const gltf::GltfOptions& options = {})
    {
        try {
            gltf::loadGltf(path, options);
        } catch (const gltf::GltfError& error) {
            return error.what();
        }
        return {};
    }

    std::filesystem::path folder_;
};

// One cube mesh under one root node: the smallest scene with geometry.
inline GltfBuilder cubeScene(Component indices = Component::UnsignedShort)
{
    GltfBuilder b;
    const int mesh = testing::addCubeMesh(b, "Cube", -1, indices);
    b.addRoot(b.add("nodes", {{"name", "cube"}, {"mesh", mesh}}));
    return b;
}

inline nlohmann::json& primitive(GltfBuilder& b, int mesh = 0)
{
    return b.json()["meshes"][std::size_t(mesh)]["primitives"][0];
}

inline int attribute(GltfBuilder& b, const char* name) { return primitive(b)["attributes"][name].get<int>(); }

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

} // namespace penumbra::scene
