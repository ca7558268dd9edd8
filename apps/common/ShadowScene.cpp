#include "ShadowScene.hpp"

#include "ImageFiles.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/AtlasPicture.hpp"
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::apps {

scene::Scene namedScene(const std::string& name)
{
    if (name == "test")
        return scene::makeShadowTestScene();
    if (name == "key-light")
        return scene::makeSingleLightScene();
    if (name == "mixed")
        return scene::makeMixedLightsScene();
    if (name == "room")
        return scene::makePointLightRoomScene();
    throw rhi::Error(fmt::format("no scene named '{}'; known scenes: test, key-light, mixed, room", name));
}

namespace {

rhi::DepthImage cubeFacesSideBySide(rhi::Device& device, const shadows::ShadowCubes& cubes)
{
    const std::uint32_t size = cubes.faceSize();
    rhi::DepthImage strip{6 * size, size, std::vector<float>(std::size_t(6) * size * size)};
    for (const rhi::CubeFace face : rhi::allCubeFaces) {
        const rhi::DepthImage one = rhi::readDepth(device, cubes.texture(), rhi::cubeLayer(0, face));
        for (std::uint32_t y = 0; y < size; ++y)
            std::copy_n(one.depth.begin() + std::ptrdiff_t(y) * size, size,
                        strip.depth.begin() + std::ptrdiff_t(y) * strip.width + std::ptrdiff_t(face) * size);
    }
    return strip;
}

} // namespace

ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame)
{
    auto device = createDevice(configuration);
    render::SceneRenderer renderer(*device, scene);
    ShadowPictures pictures;
    pictures.configuration = configuration;
    pictures.depthRange = device->conventions().depthRange();
    pictures.reversedZ = device->conventions().reversedZ();
    render::FrameDesc withCascades = frame;
    withCascades.cascadeView = true;
    pictures.stats = renderer.render(scene.camera, withCascades);
    pictures.notes = renderer.notes();
    pictures.lit = rhi::readTexture(*device, renderer.litImage());
    pictures.cascades = rhi::readTexture(*device, renderer.cascadeImage());
    pictures.atlasDepth = rhi::readDepth(*device, renderer.atlas().texture());
    pictures.atlas = render::atlasPicture(pictures.atlasDepth, device->conventions());
    pictures.atlasLightDepth = render::lightDepthFraction(pictures.atlasDepth, device->conventions());
    pictures.otherAtlasDepth = rhi::readDepth(*device, renderer.otherAtlas().texture());
    const std::vector<render::PerspectiveTile> tiles = render::perspectiveTiles(renderer.otherPlan());
    pictures.otherAtlas = render::atlasPicture(pictures.otherAtlasDepth, device->conventions(), tiles);
    pictures.otherAtlasNearness = render::lightDepthFraction(pictures.otherAtlasDepth, device->conventions());
    if (!renderer.otherPlan().cubes.empty()) {
        pictures.cubeFacesDepth = cubeFacesSideBySide(*device, renderer.shadowCubes());
        pictures.cubeFacesNearness = render::lightDepthFraction(pictures.cubeFacesDepth, device->conventions());
    }
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return pictures;
}

void writeShadowPictures(const std::filesystem::path& folder, const ShadowPictures& pictures)
{
    writePng(folder / "lit.png", pictures.lit);
    writePng(folder / "atlas.png", pictures.atlas);
    writeExr(folder / "atlas.exr", pictures.atlasDepth);
    writePng(folder / "cascades.png", pictures.cascades);
    writePng(folder / "other-atlas.png", pictures.otherAtlas);
    writeExr(folder / "other-atlas.exr", pictures.otherAtlasDepth);
}

} // namespace penumbra::apps
