#include "LocalLightTextures.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

std::uint32_t rowsFor(std::size_t texels)
{
    const auto rows = static_cast<std::uint32_t>((texels + kLitDataTextureWidth - 1) / kLitDataTextureWidth);
    return std::bit_ceil(std::max(rows, 1u));
}

} // namespace

// A texture of at least `rows` rows of this usage, made anew where the last one is too small or of another usage.
void LocalLightTextures::reserve(DataTexture& target, rhi::Format format, const char* name, std::uint32_t rows,
                                 rhi::TextureUsage usage)
{
    if (target.texture && target.texture->desc().height >= rows && target.texture->desc().usage == usage)
        return;
    target.texture = device_.createTexture(
        {.width = kLitDataTextureWidth, .height = rows, .format = format, .usage = usage, .debugName = name});
    target.uploaded.clear();
}

// The texture with room for `data`, made anew (twice as many rows, or more) when too small; `data` uploaded into its
// first texels, the rest zero, unless that is what it holds: an upload waits for the device (Device::writeTexture).
void LocalLightTextures::upload(DataTexture& target, rhi::Format format, const char* name,
                                std::span<const std::byte> data)
{
    const std::size_t texelBytes = rhi::texelSize(format);
    reserve(target, format, name, rowsFor(data.size() / texelBytes), rhi::TextureUsage::Sampled);
    std::vector<std::byte> level(std::size_t(kLitDataTextureWidth) * target.texture->desc().height * texelBytes);
    std::memcpy(level.data(), data.data(), data.size());
    if (level == target.uploaded)
        return;
    device_.writeTexture(*target.texture, 0, 0, level);
    target.uploaded = std::move(level);
}

std::vector<LocalLightRecord> localLightRecords(const scene::Scene& scene, const shadows::LocalShadowPlan& plan,
                                                const shadows::StaticShadowPlan& staticPlan,
                                                std::span<const std::uint32_t> contactLights)
{
    std::vector<LocalLightRecord> records;
    records.reserve(scene.spotLights.size() + scene.pointLights.size());
    // Light `light`'s common fields: where it is, its colour, its shadow tile and static map.
    // Light `light`'s bit in the contact shadow texture, or -1.
    const auto contactBit = [&](std::size_t light) {
        const auto found = std::find(contactLights.begin(), contactLights.end(), light);
        return found == contactLights.end() ? -1.0f : static_cast<float>(found - contactLights.begin());
    };
    const auto record = [&](std::size_t light, const auto& l, scene::LightKind kind, std::int32_t shadowTile) {
        const shadows::StaticLocalLightMap map = light < staticPlan.localLightMaps.size()
                                                     ? staticPlan.localLightMaps[light]
                                                     : shadows::StaticLocalLightMap{};
        return LocalLightRecord{.position = l.position,
                                .inverseRangeSquared = 1.0f / (l.range * l.range),
                                .color = l.color * l.intensity,
                                .kind = static_cast<float>(kind),
                                .contactBit = contactBit(light),
                                .shadowTile = static_cast<float>(shadowTile),
                                .shadowStrength = l.shadowStrength,
                                .staticTile = static_cast<float>(map.tile),
                                .staticStrength = map.strength};
    };
    for (std::size_t i = 0; i < scene.spotLights.size(); ++i) {
        const scene::SpotLight& l = scene.spotLights[i];
        LocalLightRecord spot = record(i, l, scene::LightKind::Spot, plan.spotTiles[i]);
        // Smooth step of the cone: saturate(cos(angle) * a + b), 0 at the outer, 1 at the inner angle.
        const float cosOuter = std::cos(l.outerAngle);
        spot.axis = l.direction;
        spot.coneScale = 1.0f / std::max(std::cos(l.innerAngle) - cosOuter, 1e-3f);
        spot.coneOffset = -cosOuter * spot.coneScale;
        records.push_back(spot);
    }
    for (std::size_t i = 0; i < scene.pointLights.size(); ++i)
        records.push_back(
            record(scene.spotLights.size() + i, scene.pointLights[i], scene::LightKind::Point, plan.pointShadows[i]));
    return records;
}

std::vector<shadows::ClusterLight> clusterLights(const scene::Scene& scene)
{
    std::vector<shadows::ClusterLight> lights;
    lights.reserve(scene.spotLights.size() + scene.pointLights.size());
    // The scene keeps spot cones within (0, pi / 2), as the clusters need them.
    for (const scene::SpotLight& l : scene.spotLights)
        lights.push_back({shadows::LightKind::Spot, l.position, l.range, glm::normalize(l.direction), l.outerAngle});
    for (const scene::PointLight& l : scene.pointLights)
        lights.push_back({shadows::LightKind::Point, l.position, l.range});
    return lights;
}

void setClusterView(LitFrameUniforms& u, const shadows::ShadowCamera& camera, const shadows::LightClusterUniforms& grid)
{
    // As buildLightClusters' view frame.
    const float tanHalf = std::tan(0.5f * camera.fovY);
    u.cameraRight = glm::normalize(glm::cross(camera.forward, camera.up));
    u.tanHalfFovX = camera.aspect * tanHalf;
    u.cameraUp = camera.up;
    u.tanHalfFovY = tanHalf;
    u.clusterNear = grid.nearPlane;
    u.clusterFar = grid.farPlane;
    u.clusterSliceScale = grid.sliceScale;
    u.clusterSliceBias = grid.sliceBias;
}

LocalLightTextures::LocalLightTextures(rhi::Device& device)
    : device_(device),
      sampler_(device.createSampler(
          {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "local light data"}))
{
}

void LocalLightTextures::updateLights(std::span<const LocalLightRecord> lights)
{
    upload(lights_, kLocalLightFormat, "local lights", std::as_bytes(lights));
}

shadows::LightClusterUniforms LocalLightTextures::prepareLists(const shadows::ShadowCamera& camera,
                                                               std::span<const shadows::ClusterLight> lights,
                                                               shadows::LightClusterBuild build)
{
    gpuInputs_.reset();
    if (build == shadows::LightClusterBuild::Gpu) {
        gpuInputs_ = shadows::lightClusterInputs(camera, lights, kLitClusterGrid);
        const rhi::TextureUsage usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage;
        const shadows::LightClusterUniforms& g = gpuInputs_->grid;
        reserve(clusters_, kLightClusterFormat, "light clusters", rowsFor(std::size_t(g.tilesX) * g.tilesY * g.slices),
                usage);
        reserve(indices_, kLightIndexFormat, "light indices", rowsFor(gpuInputs_->entryBound), usage);
        if (!gpuBuild_)
            gpuBuild_ = std::make_unique<shadows::GpuLightClusters>(device_);
        return g;
    }
    const shadows::LightClusters clusters = shadows::buildLightClusters(camera, lights, kLitClusterGrid);
    std::vector<glm::vec4> ranges(clusters.ranges.size());
    for (std::size_t c = 0; c < ranges.size(); ++c)
        ranges[c] = {static_cast<float>(clusters.ranges[c].offset), static_cast<float>(clusters.ranges[c].count), 0.0f,
                     0.0f};
    upload(clusters_, kLightClusterFormat, "light clusters", std::as_bytes(std::span(ranges)));
    std::vector<float> indices(clusters.lightIndices.begin(), clusters.lightIndices.end());
    upload(indices_, kLightIndexFormat, "light indices", std::as_bytes(std::span(indices)));
    return clusters.grid;
}

void LocalLightTextures::recordGpuLists(rhi::CommandList& commands, const rhi::Texture& ranges,
                                        const rhi::Texture& indices)
{
    gpuBuild_->record(commands, *gpuInputs_, ranges, indices);
    // What the textures hold is the GPU's now: the next CPU frame uploads whatever it builds.
    clusters_.uploaded.clear();
    indices_.uploaded.clear();
}

void LocalLightTextures::bind(rhi::CommandList& commands) const
{
    commands.bindTexture(kLitLocalLightsBinding, lights(), *sampler_);
    commands.bindTexture(kLitLightClustersBinding, clusters(), *sampler_);
    commands.bindTexture(kLitLightIndicesBinding, indices(), *sampler_);
}

} // namespace penumbra::render
