#include "ShadowScene.hpp"

#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/AtlasPicture.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/truth/ShadowTruth.hpp"
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <span>

namespace penumbra::apps {
namespace {

AtlasPictures atlasPictures(std::string name, rhi::DepthImage depth, const rhi::Conventions& conventions,
                            std::span<const render::PerspectiveTile> perspectiveTiles = {})
{
    AtlasPictures atlas{std::move(name), {}, std::move(depth), {}};
    atlas.picture = render::atlasPicture(atlas.depth, conventions, perspectiveTiles);
    atlas.lightDepth = render::lightDepthFraction(atlas.depth, conventions);
    return atlas;
}

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

namespace {

struct NamedScene {
    std::string_view name;
    scene::Scene (*make)();
};

constexpr std::array<NamedScene, 12> kNamedScenes{{{"test", scenes::makeShadowTestScene},
                                                   {"key-light", scenes::makeSingleLightScene},
                                                   {"mixed", scenes::makeMixedLightsScene},
                                                   {"room", scenes::makePointLightRoomScene},
                                                   {"forest", scenes::makeForestScene},
                                                   {"contact", scenes::makeContactScene},
                                                   {"contact-local", scenes::makeContactLocalLightsScene},
                                                   {"town", scenes::makeTownScene},
                                                   {"street", scenes::makeStreetScene},
                                                   {"cubes", [] { return scenes::makeCubeGridScene(10'000); }},
                                                   {"cubes-100k", [] { return scenes::makeCubeGridScene(100'000); }},
                                                   {"cubes-1m", [] { return scenes::makeCubeGridScene(1'000'000); }}}};

} // namespace

bool isNamedScene(std::string_view name)
{
    return std::any_of(kNamedScenes.begin(), kNamedScenes.end(), [&](const NamedScene& s) { return s.name == name; });
}

scene::Scene namedScene(const std::string& name)
{
    for (const NamedScene& s : kNamedScenes)
        if (s.name == name)
            return s.make();
    throw rhi::Error(fmt::format("no scene named '{}'; known scenes: {}", name, kSceneNames));
}

ShadowPictures renderShadowScene(rhi::Device& device, const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame, bool readAtlases,
                                 const shadows::StaticShadowBake* bake)
{
    render::SceneRenderer renderer(device, scene);
    if (bake)
        renderer.useBakedShadows(*bake);
    ShadowPictures pictures;
    pictures.configuration = configuration;
    pictures.depthRange = device.conventions().depthRange();
    pictures.reversedZ = device.conventions().reversedZ();
    // Depth fit plans with the last frame's reduction: a first frame reduces the view's depths, as a running
    // application's previous frame would have.
    if (frame.shadows.directional.projection == shadows::CascadeProjection::DepthFit)
        renderer.render(scene.camera, frame);
    pictures.stats = renderer.render(scene.camera, frame);
    pictures.notes = renderer.notes();
    pictures.frameGraph = renderer.frameGraphDot();
    if (!scene.lights.empty())
        for (const float depth : kTexelDensityDepths)
            pictures.texelsPerMetre.push_back(truth::directionalTexelsPerMetre(renderer.plan(), 0, scene.camera,
                                                                               float(frame.width) / float(frame.height),
                                                                               depth));
    pictures.directionalPlan = renderer.plan();
    pictures.lit = rhi::readTexture(device, renderer.litImage());
    if (frame.cascadeView)
        pictures.cascades = rhi::readTexture(device, renderer.cascadeImage());
    if (!readAtlases)
        return pictures;
    const rhi::Conventions& conventions = device.conventions();
    pictures.atlases.push_back(
        atlasPictures("directional", rhi::readDepth(device, renderer.atlas().texture()), conventions));
    pictures.atlases.push_back(atlasPictures("other", rhi::readDepth(device, renderer.localAtlas().texture()),
                                             conventions, render::perspectiveTiles(renderer.localPlan())));
    if (!renderer.localPlan().cubes.empty())
        pictures.atlases.push_back(
            atlasPictures("cube", cubeFacesSideBySide(device, renderer.shadowCubes()), conventions));
    // The static maps, where the frame kept any: compared across configurations as the realtime atlases are.
    const shadows::StaticShadowPlan& statics = renderer.staticPlan();
    const auto has = [&](bool directional) {
        return std::any_of(statics.maps.begin(), statics.maps.end(), [&](const shadows::StaticShadowMap& m) {
            return (m.kind == shadows::LightKind::Directional) == directional;
        });
    };
    if (has(true))
        pictures.atlases.push_back(atlasPictures("static-directional",
                                                 rhi::readDepth(device, renderer.staticDirectionalAtlas().texture()),
                                                 conventions));
    if (has(false))
        pictures.atlases.push_back(atlasPictures("static-other",
                                                 rhi::readDepth(device, renderer.staticLocalAtlas().texture()),
                                                 conventions, render::perspectiveTiles(statics)));
    return pictures;
}

ShadowPictures renderShadowScene(const std::string& configuration, const scene::Scene& scene,
                                 const render::FrameDesc& frame, const ShadowSceneRun& run)
{
    rhi::DeviceDesc desc = toolDeviceDesc(configuration);
    desc.validation = run.validate;
    desc.validateUsage = desc.validateUsage || run.validate;
    auto device = createDevice(desc);
    ShadowPictures pictures = renderShadowScene(*device, configuration, scene, frame, run.readAtlases, run.bake);
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return pictures;
}

truth::OnScreenTexelDensity texelsOnScreen(const ShadowPictures& pictures, const scene::Scene& scene,
                                           const truth::CpuGBuffer& gbuffer)
{
    return truth::directionalTexelsOnScreen(pictures.directionalPlan, 0, scene.camera, gbuffer);
}

truth::CpuGBuffer texelDensityGBuffer(const scene::Scene& scene, const render::FrameDesc& frame)
{
    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    return truth::traceGBuffer(scene, cameraRays, scene.camera, std::max(frame.width / kTexelDensityStride, 1u),
                               std::max(frame.height / kTexelDensityStride, 1u));
}

std::vector<parity::Picture> parityPictures(const ShadowPictures& pictures)
{
    std::vector<parity::Picture> out{parity::colorPicture("lit", pictures.lit)};
    for (const AtlasPictures& atlas : pictures.atlases)
        out.push_back(parity::depthPicture(atlasFileStem(atlas.name), atlas.depth, atlas.lightDepth));
    return out;
}

std::string atlasFileStem(std::string_view name)
{
    return name == "directional" ? std::string("atlas") : fmt::format("{}-atlas", name);
}

} // namespace penumbra::apps
