// An animated skin drawn through every configuration: the two-bone bend posed (scene::poseScene, skinned on the GPU)
// at two times gives different pictures, each the same on every configuration.
#include "GltfAnimationScenes.hpp"
#include "GpuTesting.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/Posing.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

namespace penumbra::testing {
namespace {

constexpr std::array<float, 2> kTimes{0.0f, 1.0f};

TEST(AnimationParity, TheTwoBoneBendIsTheSamePictureOnEveryConfigurationAtEachTime)
{
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("penumbra-bend-" + std::to_string(::getpid()) + ".glb");
    twoBoneBendScene().writeGlb(path);
    scene::Scene scene = gltf::loadGltf(path).scene;
    std::filesystem::remove(path);
    const render::FrameDesc frame{.width = 160, .height = 120};
    std::map<std::string, std::array<rhi::Image, 2>> pictures;
    reportSkipped(forEachConfiguration([&](rhi::Device& device, const std::string& configuration) {
        // One renderer posed at each time in turn, as a playing animation is: skinned on the GPU each frame.
        render::SceneRenderer renderer(device, scene);
        for (std::size_t t = 0; t < kTimes.size(); ++t) {
            scene::poseScene(scene, scene::findAnimation(scene.rig, "bend"), kTimes[t]);
            renderer.render(scene.camera, frame);
            pictures[configuration][t] = rhi::readTexture(device, renderer.litImage());
        }
    }));
    ASSERT_FALSE(pictures.empty());
    for (const auto& [configuration, times] : pictures) {
        // The bar leans over to -x at t = 1: the pictures differ where it stood and where it bends to.
        EXPECT_GT(differingPixels(times[0], times[1], 0), 200u) << configuration;
        const auto& [first, reference] = *pictures.begin();
        for (std::size_t t = 0; t < kTimes.size(); ++t)
            EXPECT_EQ(differingPixels(reference[t], times[t], 0), 0u)
                << "t = " << kTimes[t] << ": " << savePicture(reference[t], "bend-reference-" + first) << " vs "
                << savePicture(times[t], "bend-" + configuration);
    }
}

} // namespace
} // namespace penumbra::testing
