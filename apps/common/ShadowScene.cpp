#include "ShadowScene.hpp"

#include "ImageFiles.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/AtlasPicture.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <fmt/format.h>

namespace penumbra::apps {
namespace {

AtlasPictures readAtlas(std::string name, rhi::Device& device, const rhi::Texture& texture)
{
    AtlasPictures atlas{std::move(name), {}, rhi::readDepth(device, texture), {}};
    atlas.picture = render::atlasPicture(atlas.depth, device.conventions());
    atlas.lightDepth = render::lightDepthFraction(atlas.depth, device.conventions());
    return atlas;
}

} // namespace

const AtlasPictures& ShadowPictures::atlas(std::string_view name) const
{
    std::string names;
    for (const AtlasPictures& a : atlases) {
        if (a.name == name)
            return a;
        names += (names.empty() ? "" : ", ") + a.name;
    }
    throw rhi::Error(fmt::format("{}: no atlas named '{}'; there are: {}", configuration, name, names));
}

scene::Scene namedScene(const std::string& name)
{
    if (name == "test")
        return scene::makeShadowTestScene();
    if (name == "key-light")
        return scene::makeSingleLightScene();
    throw rhi::Error(fmt::format("no scene named '{}'; known scenes: {}", name, kSceneNames));
}

ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame)
{
    auto device = createDevice(configuration);
    render::SceneRenderer renderer(*device, scene);
    ShadowPictures pictures;
    pictures.configuration = configuration;
    pictures.depthRange = device->conventions().depthRange();
    pictures.reversedZ = device->conventions().reversedZ();
    pictures.stats = renderer.render(scene.camera, frame);
    pictures.notes = renderer.notes();
    pictures.lit = rhi::readTexture(*device, renderer.litImage());
    if (frame.cascadeView)
        pictures.cascades = rhi::readTexture(*device, renderer.cascadeImage());
    pictures.atlases.push_back(readAtlas("directional", *device, renderer.atlas().texture()));
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return pictures;
}

std::string atlasFileStem(std::string_view name)
{
    return name == "directional" ? std::string("atlas") : fmt::format("{}-atlas", name);
}

void writeShadowPictures(const std::filesystem::path& folder, const ShadowPictures& pictures)
{
    writePng(folder / "lit.png", pictures.lit);
    for (const AtlasPictures& atlas : pictures.atlases) {
        writePng(folder / (atlasFileStem(atlas.name) + ".png"), atlas.picture);
        writeExr(folder / (atlasFileStem(atlas.name) + ".exr"), atlas.depth);
    }
    if (!pictures.cascades.bytes.empty())
        writePng(folder / "cascades.png", pictures.cascades);
}

} // namespace penumbra::apps
