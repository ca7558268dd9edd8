// Clustered light lists built on the GPU (local.clusterBuild gpu, shaders/light_clusters.comp): every cluster's list
// is the CPU build's (shadows::buildLightClusters, itself checked against the brute-force reference in
// LightClustersTest), entry for entry, on the street's first 32 lamps and 8 shop windows; and the street's picture is
// the same byte for byte with either build.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shadows/GpuLightClusters.hpp"

#include <algorithm>
#include <cstring>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <utility>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kDataWidth = 1024; // as the lit pass's data textures

// The street with its first 32 lamps (spot lights) and 8 shop windows (point lights).
scene::Scene smallStreet()
{
    scene::Scene scene = scenes::makeStreetScene();
    scene.spotLights.resize(32);
    scene.pointLights.resize(8);
    scene.validate();
    return scene;
}

shadows::ShadowCamera viewOf(const scene::Camera& camera, float aspect)
{
    const glm::vec3 up = glm::normalize(glm::cross(camera.right(), camera.forward));
    return {camera.position, camera.forward, up, camera.fovY, aspect, camera.nearPlane, camera.farPlane};
}

std::vector<shadows::ClusterLight> reachOf(const scene::Scene& scene)
{
    std::vector<shadows::ClusterLight> lights;
    for (const scene::SpotLight& l : scene.spotLights)
        lights.push_back({shadows::LightKind::Spot, l.position, l.range, glm::normalize(l.direction), l.outerAngle});
    for (const scene::PointLight& l : scene.pointLights)
        lights.push_back({shadows::LightKind::Point, l.position, l.range});
    return lights;
}

std::vector<float> readFloats(rhi::Device& device, const rhi::Texture& texture)
{
    const rhi::Image image = rhi::readTexture(device, texture);
    std::vector<float> values(image.bytes.size() / sizeof(float));
    std::memcpy(values.data(), image.bytes.data(), image.bytes.size());
    return values;
}

// Each cluster's list of lights.
using ClusterLists = std::vector<std::vector<std::uint32_t>>;
// Each cluster's first entry and length.
using ClusterRanges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

ClusterLists listsOf(const shadows::LightClusters& clusters)
{
    ClusterLists lists;
    for (const shadows::LightClusterRange& range : clusters.ranges)
        lists.emplace_back(clusters.lightIndices.begin() + range.offset,
                           clusters.lightIndices.begin() + range.offset + range.count);
    return lists;
}

class GpuLightClustersTest : public GpuTest {
protected:
    // The CPU's lists and the GPU's for the small street's view; `fault` changes what the GPU is given.
    template <typename Fault>
    void buildBoth(Fault fault, ClusterLists& cpu, ClusterLists& gpu, ClusterRanges& cpuRanges,
                   ClusterRanges& gpuRanges)
    {
        const scene::Scene scene = smallStreet();
        const shadows::ShadowCamera view = viewOf(scene.camera, 16.0f / 9.0f);
        const std::vector<shadows::ClusterLight> lights = reachOf(scene);
        const shadows::LightClusters clusters = shadows::buildLightClusters(view, lights);
        cpu = listsOf(clusters);
        cpuRanges.clear();
        for (const shadows::LightClusterRange& range : clusters.ranges)
            cpuRanges.emplace_back(range.offset, range.count);
        shadows::LightClusterInputs inputs = shadows::lightClusterInputs(view, lights);
        fault(inputs);
        const auto rowsFor = [](std::uint64_t texels) {
            return static_cast<std::uint32_t>((texels + kDataWidth - 1) / kDataWidth);
        };
        const auto storage = rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage;
        auto ranges = device->createTexture({.width = kDataWidth,
                                             .height = rowsFor(clusters.ranges.size()),
                                             .format = rhi::Format::RGBA32F,
                                             .usage = storage,
                                             .debugName = "ranges"});
        auto indices = device->createTexture({.width = kDataWidth,
                                              .height = rowsFor(inputs.entryBound),
                                              .format = rhi::Format::R32F,
                                              .usage = storage,
                                              .debugName = "indices"});
        shadows::GpuLightClusters build(*device);
        auto commands = device->createCommandList();
        build.record(*commands, inputs, *ranges, *indices);
        device->submit(*commands);
        const std::vector<float> rangeTexels = readFloats(*device, *ranges);
        const std::vector<float> indexTexels = readFloats(*device, *indices);
        gpu.clear();
        gpuRanges.clear();
        for (std::size_t c = 0; c < clusters.ranges.size(); ++c) {
            const auto first = static_cast<std::uint32_t>(rangeTexels[4 * c]);
            const auto count = static_cast<std::uint32_t>(rangeTexels[4 * c + 1]);
            gpuRanges.emplace_back(first, count);
            std::vector<std::uint32_t>& list = gpu.emplace_back();
            for (std::uint32_t e = first; e < first + count && e < indexTexels.size(); ++e)
                list.push_back(static_cast<std::uint32_t>(indexTexels[e]));
        }
    }
};

TEST_F(GpuLightClustersTest, ListsMatchTheCpuBuild)
{
    ClusterLists cpu, gpu;
    ClusterRanges cpuRanges, gpuRanges;
    buildBoth([](auto&) {}, cpu, gpu, cpuRanges, gpuRanges);
    EXPECT_TRUE(gpuRanges == cpuRanges) << "the clusters' first entries or lengths differ";
    ASSERT_EQ(gpu.size(), cpu.size());
    for (std::size_t c = 0; c < cpu.size(); ++c)
        EXPECT_EQ(gpu[c], cpu[c]) << "cluster " << c;
    // Not a trivial case: many clusters list several lights, some both kinds, and many list none.
    std::size_t several = 0, empty = 0;
    for (const std::vector<std::uint32_t>& list : cpu) {
        several += list.size() > 1 ? 1 : 0;
        empty += list.empty() ? 1 : 0;
    }
    EXPECT_GT(several, 100u);
    EXPECT_GT(empty, 100u);
}

// The comparison sees a light's bounding sphere shrunk to half its radius: the GPU leaves it out of clusters it
// reaches.
TEST_F(GpuLightClustersTest, ShrunkenBoundCatchesFault)
{
    ClusterLists cpu, gpu;
    ClusterRanges cpuRanges, gpuRanges;
    buildBoth([](shadows::LightClusterInputs& inputs) { inputs.lights[3].bound.w *= 0.5f; }, cpu, gpu, cpuRanges,
              gpuRanges);
    EXPECT_NE(gpu, cpu);
}

// One renderer draws both frames (the second with the first's cached local tiles, which LocalTileCacheTest holds to
// a fresh renderer's), switching the build between them.
TEST_F(GpuLightClustersTest, PicturesMatchTheCpuBuild)
{
    const scene::Scene scene = smallStreet();
    render::SceneRenderer renderer(*device, scene);
    const auto draw = [&](shadows::LightClusterBuild build) {
        render::FrameDesc frame = litFrame(160, 90, true, 1);
        frame.shadows.local.clusterBuild = build;
        frame.shadows.directional.atlasSize = 512;
        frame.shadows.local.atlasSize = 512;
        const render::FrameStats stats = renderer.render(scene.camera, frame);
        const bool ran = std::any_of(stats.passes.begin(), stats.passes.end(), [](const render::PassTiming& pass) {
            return pass.name == render::frame::kLightClusterPass;
        });
        EXPECT_EQ(ran, build == shadows::LightClusterBuild::Gpu);
        return rhi::readTexture(*device, renderer.litImage());
    };
    const rhi::Image cpu = draw(shadows::LightClusterBuild::Cpu);
    const rhi::Image gpu = draw(shadows::LightClusterBuild::Gpu);
    EXPECT_TRUE(cpu.bytes == gpu.bytes) << "the lit images differ: "
                                        << savePicture(cpu, "gpu-clusters-cpu-" + configuration()) << " "
                                        << savePicture(gpu, "gpu-clusters-gpu-" + configuration());
}

} // namespace
} // namespace penumbra::testing
