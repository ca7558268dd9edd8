// What a user meets first with a file the project has never seen: files that cannot be read named with the file,
// position or element (a missing image, a truncated file, enormous positions), and the stand-in for a missing image.
#include "GltfLoaderFixture.hpp"

#include "penumbra/gltf/GltfLoader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <regex>

namespace penumbra::scene {
namespace {

TEST_F(GltfLoaderTest, MissingImageIsNamedByItsUriAndThePathTried)
{
    const std::filesystem::path path = write(testing::missingImageScene());
    EXPECT_THROW(gltf::loadGltf(path), gltf::GltfMissingImageError);
    EXPECT_CONTAINS(errorOf(path), "scene.gltf: material 0 ('painted'): pbrMetallicRoughness.baseColorTexture: image 0 "
                                   "'textures/albedo.png' cannot be read (tried " +
                                       (folder_ / "textures" / "albedo.png").string() + ")");
}

TEST_F(GltfLoaderTest, MissingImageStandsInWhenAsked)
{
    const gltf::GltfScene loaded =
        gltf::loadGltf(write(testing::missingImageScene()), {.missingTextures = gltf::MissingTextures::StandIn});
    ASSERT_EQ(loaded.scene.materials.size(), 1u);
    EXPECT_FALSE(loaded.scene.materials[0].texture(TextureSlot::BaseColor).has_value());
    EXPECT_TRUE(loaded.scene.textures.empty());
    std::string all;
    for (const std::string& note : loaded.notes)
        all += note + "\n";
    EXPECT_CONTAINS(all, "textures/albedo.png cannot be read: drawn with a flat stand-in");
    // tinygltf's own warnings about the file are replaced by that note.
    EXPECT_EQ(all.find("File not found"), std::string::npos) << all;
}

TEST_F(GltfLoaderTest, TruncatedFileErrorNamesThePositionWithAShortExcerpt)
{
    const std::string text = testing::truncatedGltf(testing::largeTexturesScene(1, 64));
    ASSERT_GT(text.size(), 10000u);
    const std::filesystem::path path = folder_ / "cut.gltf";
    std::ofstream(path, std::ios::binary) << text;
    const std::string error = errorOf(path);
    EXPECT_CONTAINS(error, fmt::format("cut.gltf: cannot read: JSON syntax error while parsing value - invalid string: "
                                       "missing closing quote at byte {} of {}",
                                       text.size(), text.size()));
    EXPECT_CONTAINS(error, "\"uri\": \"data:application/octet-stream;base64,");
    EXPECT_LT(error.size(), 400u) << error;
    // No run of the base64 payload longer than the excerpt keeps of a string.
    EXPECT_FALSE(std::regex_search(error.substr(error.find("after: ")), std::regex("[A-Za-z0-9+/]{48}"))) << error;
}

// One triangle with a vertex at `far` on y, under a node scaled by `scale`.
GltfBuilder triangleScene(float far, float scale = 1.0f)
{
    GltfBuilder b;
    const std::array<glm::vec3, 3> positions{{{0, 0, 0}, {1, 0, 0}, {0, far, 0}}};
    const int mesh = b.add("meshes", {{"name", "spike"},
                                      {"primitives", {{{"attributes", {{"POSITION", b.addPositions(positions)}}}}}}});
    b.addRoot(b.add("nodes", {{"name", "spike"}, {"mesh", mesh}, {"scale", {scale, scale, scale}}}));
    return b;
}

TEST_F(GltfLoaderTest, EnormousPositionsAreRefusedByAccessorElementAndLimit)
{
    EXPECT_CONTAINS(errorOf(write(triangleScene(3e25f), "huge.gltf")),
                    "huge.gltf: mesh 0 ('spike') primitive 0: accessor 0 (POSITION) element 2 is (0, 3e+25, 0), over "
                    "the limit of 1e+16 for a coordinate");
    EXPECT_CONTAINS(errorOf(write(triangleScene(1e10f, 1e10f), "scaled.gltf")),
                    "scaled.gltf: mesh 0 ('spike') primitive 0: accessor 0 (POSITION) under the transform of object "
                    "'spike' reaches (1e+10, 1e+20, 0) in world space, over the limit of 1e+16 for a coordinate");
}

TEST_F(GltfLoaderTest, LargeButValidPositionsLoadWithADefaultCameraAndSun)
{
    for (const float far : {1e6f, 1e12f, 1e16f}) {
        const gltf::GltfScene loaded = gltf::loadGltf(write(triangleScene(far)));
        EXPECT_NO_THROW(loaded.scene.validate()) << far;
        EXPECT_EQ(loaded.scene.lights.size(), 1u) << far;
    }
}

} // namespace
} // namespace penumbra::scene
