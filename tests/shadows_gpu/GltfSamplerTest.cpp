// A glTF file's samplers and textures as the RHI receives them: filters, wrap modes, sRGB format, CPU-made mip
// chains, and the frame's anisotropy clamped to the device with a note.
#include "GltfBuilder.hpp"
#include "GpuTesting.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

class GltfSamplerTest : public GpuTest {
protected:
    // Cube 0: NEAREST / NEAREST_MIPMAP_LINEAR, MIRRORED_REPEAT x CLAMP_TO_EDGE; cube 1: no sampler (repeat,
    // trilinear); cube 2: LINEAR without mipmaps, REPEAT x MIRRORED_REPEAT.
    scene::Scene load()
    {
        const GltfBuilder b =
            sampledTexturesScene({{{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33648}, {"wrapT", 33071}},
                                  nullptr,
                                  {{"magFilter", 9729}, {"minFilter", 9729}, {"wrapT", 33648}}});
        const std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("penumbra-samplers-" + configuration() + ".glb");
        b.writeGlb(path);
        scene::Scene scene = gltf::loadGltf(path).scene;
        std::filesystem::remove(path);
        return scene;
    }

    static const scene::Material& material(const scene::Scene& scene, int cube)
    {
        return scene.materialOf(scene.objects.at(*scene.findObject("cube " + std::to_string(cube))));
    }
};

TEST_F(GltfSamplerTest, FileSamplersReachTheRhiSamplers)
{
    const scene::Scene scene = load();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc frame{.width = 64, .height = 36, .maxAnisotropy = 4.0f};
    renderer.render(scene.camera, frame);
    const render::GpuScene& gpu = renderer.gpuScene();

    const rhi::SamplerDesc mirrored = gpu.baseColorSampler(material(scene, 0)).desc();
    EXPECT_EQ(mirrored.magFilter, rhi::Filter::Nearest);
    EXPECT_EQ(mirrored.minFilter, rhi::Filter::Nearest);
    EXPECT_EQ(mirrored.mipFilter, rhi::MipFilter::Linear);
    EXPECT_EQ(mirrored.addressU, rhi::AddressMode::MirroredRepeat);
    EXPECT_EQ(mirrored.addressV, rhi::AddressMode::ClampToEdge);
    EXPECT_EQ(mirrored.maxAnisotropy, 1.0f) << "nearest texels are not filtered anisotropically";

    const rhi::SamplerDesc trilinear = gpu.baseColorSampler(material(scene, 1)).desc();
    EXPECT_EQ(trilinear.minFilter, rhi::Filter::Linear);
    EXPECT_EQ(trilinear.mipFilter, rhi::MipFilter::Linear);
    EXPECT_EQ(trilinear.addressU, rhi::AddressMode::Repeat);
    EXPECT_EQ(trilinear.addressV, rhi::AddressMode::Repeat);
    EXPECT_EQ(trilinear.maxAnisotropy, std::min(4.0f, device->capabilities().maxSamplerAnisotropy));

    const rhi::SamplerDesc noMips = gpu.baseColorSampler(material(scene, 2)).desc();
    EXPECT_EQ(noMips.mipFilter, rhi::MipFilter::None);
    EXPECT_EQ(noMips.addressV, rhi::AddressMode::MirroredRepeat);

    const rhi::TextureDesc& chained = gpu.baseColorMap(material(scene, 1)).desc();
    EXPECT_EQ(chained.format, rhi::Format::RGBA8_SRGB);
    EXPECT_EQ(chained.mipLevels, 3u) << "4 x 4, 2 x 2, 1 x 1";
    EXPECT_EQ(gpu.baseColorMap(material(scene, 2)).desc().mipLevels, 1u) << "its sampler reads level 0 only";
    // The chain on the GPU is the CPU's linear-light box filter of the picture.
    const rhi::Image top = rhi::readTexture(*device, gpu.baseColorMap(material(scene, 1)), 0, 2);
    ASSERT_EQ(top.bytes.size(), 4u);
    EXPECT_EQ(std::uint8_t(top.bytes[1]), 128) << "green is 128 in every texel";
    EXPECT_EQ(std::uint8_t(top.bytes[3]), 255);
}

TEST_F(GltfSamplerTest, AnisotropyIsClampedToTheDeviceAndTheFrameSaysSo)
{
    const scene::Scene scene = load();
    render::SceneRenderer renderer(*device, scene);
    const float limit = device->capabilities().maxSamplerAnisotropy;
    render::FrameDesc frame{.width = 64, .height = 36, .maxAnisotropy = limit * 2.0f};
    const render::FrameStats stats = renderer.render(scene.camera, frame);
    EXPECT_EQ(renderer.gpuScene().baseColorSampler(material(scene, 1)).desc().maxAnisotropy, limit);
    const std::string expected = limit > 1.0f
                                     ? fmt::format("textures are sampled with anisotropy {}, the limit of", limit)
                                     : std::string("textures are sampled without anisotropic filtering");
    const bool noted = std::any_of(stats.notes.begin(), stats.notes.end(),
                                   [&](const std::string& note) { return note.find(expected) != std::string::npos; });
    EXPECT_TRUE(noted) << "expected a note containing: " << expected;

    frame.maxAnisotropy = limit;
    const render::FrameStats within = renderer.render(scene.camera, frame);
    EXPECT_TRUE(std::none_of(within.notes.begin(), within.notes.end(), [](const std::string& note) {
        return note.find("anisotropic") != std::string::npos || note.find("anisotropy") != std::string::npos;
    }));

    frame.maxAnisotropy = 0.5f;
    try {
        renderer.render(scene.camera, frame);
        ADD_FAILURE() << "maxAnisotropy 0.5 was accepted";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("FrameDesc::maxAnisotropy 0.5 is below 1"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace penumbra::testing
