#include "SoakChanges.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <algorithm>
#include <optional>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::apps {
namespace {

template <typename T, std::size_t N>
T pick(std::mt19937& random, const std::array<T, N>& values)
{
    return values[std::uniform_int_distribution<std::size_t>(0, N - 1)(random)];
}

float uniform(std::mt19937& random, float from, float to)
{
    return std::uniform_real_distribution<float>(from, to)(random);
}

std::uint32_t uniform(std::mt19937& random, std::uint32_t from, std::uint32_t to)
{
    return std::uniform_int_distribution<std::uint32_t>(from, to)(random);
}

glm::vec3 pointIn(std::mt19937& random, const scene::Bounds& bounds)
{
    const glm::vec3 lo = bounds.min, hi = bounds.max;
    // Above the objects' middle, where a light shines on something.
    return {uniform(random, lo.x, hi.x), uniform(random, bounds.center().y, hi.y + 0.5f * bounds.size().y + 1.0f),
            uniform(random, lo.z, hi.z)};
}

float sceneRange(const scene::Bounds& bounds) { return std::max(1.0f, glm::length(bounds.size())); }

constexpr std::array kAtlasSizes{256u, 512u, 1024u, 2048u};
constexpr std::array kCubeSizes{64u, 128u, 256u, 512u};
constexpr std::array kDepthFormats{rhi::Format::D16, rhi::Format::D24S8, rhi::Format::D32F};
using shadows::ShadowFilter;
constexpr std::array kFilters{ShadowFilter::PCF2x2, ShadowFilter::PCF3x3,  ShadowFilter::PCF5x5,
                              ShadowFilter::PCF7x7, ShadowFilter::Poisson, ShadowFilter::PCSS};

std::size_t localLights(const scene::Scene& scene) { return scene.spotLights.size() + scene.pointLights.size(); }

void setLightFilter(std::mt19937& random, scene::Scene& scene)
{
    // -1: the atlas's filter, else one of kFilters.
    const int pick = std::uniform_int_distribution<int>(-1, int(kFilters.size()) - 1)(random);
    const std::optional<ShadowFilter> filter =
        pick < 0 ? std::nullopt : std::optional<ShadowFilter>(kFilters[std::size_t(pick)]);
    const std::size_t lights = scene.lights.size() + localLights(scene);
    if (lights == 0)
        return;
    std::size_t i = std::uniform_int_distribution<std::size_t>(0, lights - 1)(random);
    if (i < scene.lights.size())
        return void(scene.lights[i].shadowFilter = filter);
    i -= scene.lights.size();
    if (i < scene.spotLights.size())
        return void(scene.spotLights[i].shadowFilter = filter);
    scene.pointLights[i - scene.spotLights.size()].shadowFilter = filter;
}

void moveLight(std::mt19937& random, SoakState& state)
{
    scene::Scene& scene = state.scene;
    const std::size_t lights = scene.lights.size() + localLights(scene);
    if (lights == 0)
        return;
    std::size_t i = std::uniform_int_distribution<std::size_t>(0, lights - 1)(random);
    if (i < scene.lights.size()) {
        // Anywhere in the upper half of the sky.
        scene.lights[i].direction = glm::normalize(
            glm::vec3(uniform(random, -1.0f, 1.0f), uniform(random, -1.0f, -0.2f), uniform(random, -1.0f, 1.0f)));
        return;
    }
    i -= scene.lights.size();
    if (i < scene.spotLights.size())
        return void(scene.spotLights[i].position = pointIn(random, state.bounds));
    scene.pointLights[i - scene.spotLights.size()].position = pointIn(random, state.bounds);
}

void removeLight(std::mt19937& random, scene::Scene& scene)
{
    const std::size_t lights = localLights(scene);
    if (lights == 0)
        return;
    const std::size_t i = std::uniform_int_distribution<std::size_t>(0, lights - 1)(random);
    if (i < scene.spotLights.size())
        scene.spotLights.erase(scene.spotLights.begin() + std::ptrdiff_t(i));
    else
        scene.pointLights.erase(scene.pointLights.begin() + std::ptrdiff_t(i - scene.spotLights.size()));
}

} // namespace

std::string_view soakChangeName(SoakChange change)
{
    static constexpr std::array<std::string_view, kSoakChangeCount> names = {"directionalAtlasSize",
                                                                             "localAtlasSize",
                                                                             "directionalAtlasFormat",
                                                                             "localAtlasFormat",
                                                                             "directionalFilter",
                                                                             "localFilter",
                                                                             "lightFilter",
                                                                             "cascadeCount",
                                                                             "cascadeBlend",
                                                                             "pointMode",
                                                                             "cubeMapSize",
                                                                             "softSamples",
                                                                             "anisotropy",
                                                                             "depthPrepass",
                                                                             "addPointLight",
                                                                             "addSpotLight",
                                                                             "moveLight",
                                                                             "removeLight",
                                                                             "resize",
                                                                             "sceneReload"};
    return names.at(std::size_t(change));
}

SoakChange drawSoakChange(std::mt19937& random)
{
    // A reload rebuilds every pipeline, which lavapipe and llvmpipe take seconds to compile: one change in 50.
    if (std::bernoulli_distribution(0.02)(random))
        return SoakChange::SceneReload;
    return SoakChange(std::uniform_int_distribution<std::size_t>(0, kSoakChangeCount - 2)(random));
}

void applySoakChange(SoakChange change, std::mt19937& random, SoakState& state)
{
    shadows::ShadowSettings& s = state.frame.shadows;
    switch (change) {
    case SoakChange::DirectionalAtlasSize:
        s.directional.atlasSize = pick(random, kAtlasSizes);
        break;
    case SoakChange::LocalAtlasSize:
        s.local.atlasSize = pick(random, kAtlasSizes);
        break;
    case SoakChange::DirectionalAtlasFormat:
        s.directional.atlasFormat = pick(random, kDepthFormats);
        break;
    case SoakChange::LocalAtlasFormat:
        s.local.atlasFormat = pick(random, kDepthFormats);
        break;
    case SoakChange::DirectionalFilter:
        s.directional.filter = pick(random, kFilters);
        break;
    case SoakChange::LocalFilter:
        s.local.filter = pick(random, kFilters);
        break;
    case SoakChange::LightFilter:
        setLightFilter(random, state.scene);
        break;
    case SoakChange::CascadeCount:
        s.directional.cascadeCount = uniform(random, 1u, 4u);
        break;
    case SoakChange::CascadeBlend:
        s.directional.cascadeBlend = pick(random, std::array{shadows::CascadeBlend::Hard, shadows::CascadeBlend::Soft,
                                                             shadows::CascadeBlend::Dither});
        break;
    case SoakChange::PointMode:
        s.local.pointMode = s.local.pointMode == shadows::PointShadowMode::Atlas ? shadows::PointShadowMode::CubeMap
                                                                                 : shadows::PointShadowMode::Atlas;
        break;
    case SoakChange::CubeMapSize:
        s.local.cubeMapSize = pick(random, kCubeSizes);
        break;
    case SoakChange::SoftSamples:
        s.soft.blockerSamples = pick(random, std::array{16u, 32u, 64u});
        s.soft.filterSamples = pick(random, std::array{16u, 32u, 64u});
        break;
    case SoakChange::Anisotropy:
        state.frame.maxAnisotropy = pick(random, std::array{1.0f, 2.0f, 4.0f, 8.0f, 16.0f});
        break;
    case SoakChange::DepthPrepass:
        state.frame.depthPrepass = !state.frame.depthPrepass;
        break;
    case SoakChange::AddPointLight:
        if (localLights(state.scene) < kMaxSoakLocalLights)
            state.scene.pointLights.push_back({.name = fmt::format("soak point {}", state.scene.pointLights.size()),
                                               .color = {1.0f, 0.9f, 0.7f},
                                               .position = pointIn(random, state.bounds),
                                               .range = sceneRange(state.bounds)});
        break;
    case SoakChange::AddSpotLight:
        if (localLights(state.scene) < kMaxSoakLocalLights)
            state.scene.spotLights.push_back({.name = fmt::format("soak spot {}", state.scene.spotLights.size()),
                                              .color = {0.7f, 0.9f, 1.0f},
                                              .position = pointIn(random, state.bounds),
                                              .direction = {0.0f, -1.0f, 0.0f},
                                              .range = sceneRange(state.bounds)});
        break;
    case SoakChange::MoveLight:
        moveLight(random, state);
        break;
    case SoakChange::RemoveLight:
        removeLight(random, state.scene);
        break;
    case SoakChange::Resize:
        state.frame.width = uniform(random, std::max(16u, state.start.width / 2), state.start.width);
        state.frame.height = uniform(random, std::max(16u, state.start.height / 2), state.start.height);
        break;
    case SoakChange::SceneReload:
        break;
    }
}

} // namespace penumbra::apps
