#include "penumbra/shadows/LocalShadowPlanner.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/CasterBvh.hpp"
#include "penumbra/shadows/ShadowResolution.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>

namespace penumbra::shadows {
namespace {

// A light that casts shadows and asks the packer for tiles (Atlas mode), in planning order: spot lights, then point
// lights.
struct Candidate {
    LightKind kind;
    std::uint32_t lightIndex;
    LocalLightImportance importance;
    float intensity;
};

// Why a light with shadows would shadow nothing the camera sees (Unity's
// CullingResults.GetShadowCasterBounds check, as Catlike Coding's "Directional Shadows" uses it, and the shadow
// distance), or nullopt.
struct LightReach {
    glm::vec3 position;
    float range;
    bool anyCaster; // a caster's box meets the light's frustum (spot) or range sphere (point)
};

std::optional<std::string> shadowsNothing(const LightReach& light, const ShadowCamera& camera, float maxDistance)
{
    if (!light.anyCaster)
        return std::string("no shadow caster is within its reach");
    const float nearestDepth = glm::dot(light.position - camera.position, camera.forward) - light.range;
    if (nearestDepth > maxDistance)
        return fmt::format("its reach begins at view depth {:.3g}, beyond the shadow distance {:.3g}", nearestDepth,
                           maxDistance);
    return std::nullopt;
}

// Whether a light asks for shadows at all; if not, the report says why.
bool wantsShadow(LocalShadowPlan& plan, LightKind kind, std::uint32_t index, float strength,
                 const std::optional<std::string>& nothingToShadow)
{
    if (!(strength > 0.0f)) {
        plan.report.push_back({kind, index, fmt::format("shadow strength is {}", strength)});
        return false;
    }
    if (nothingToShadow) {
        plan.report.push_back({kind, index, *nothingToShadow});
        return false;
    }
    return true;
}

ShadowAtlasPackerSettings packerSettings(const LocalShadowSettings& local)
{
    return {.atlasSize = local.atlasSize,
            .floorSize = local.minTileResolution,
            .maxSize = local.atlasSize,
            .hysteresis = ShadowAtlasPackerSettings{}.hysteresis};
}

// Each candidate's tile request: its size from its own resolution and importance, its priority for the packer.
std::vector<ShadowTileRequest> tileRequests(std::vector<Candidate>& candidates, const LocalShadowSettings& local,
                                            const ShadowCamera& camera)
{
    float brightest = 0.0f;
    for (const Candidate& c : candidates)
        brightest = std::max(brightest, c.intensity);
    const ShadowResolutionLimits limits{.floorSize = static_cast<float>(local.minTileResolution),
                                        .maxSize = static_cast<float>(local.atlasSize),
                                        .defaultSize = static_cast<float>(local.tileResolution)};
    std::vector<ShadowTileRequest> requests;
    for (Candidate& c : candidates) {
        c.importance.relativeIntensity = brightest > 0.0f ? c.intensity / brightest : 1.0f;
        const ShadowResolutionRequest r = localShadowRequest(camera, c.importance, limits);
        const bool spot = c.kind == LightKind::Spot;
        requests.push_back({spot ? spotPackerId(c.lightIndex) : pointPackerId(c.lightIndex), r.size, r.priority,
                            spot ? 1u : cubeFaceCount});
    }
    return requests;
}

// The rasteriser's biases of a view: the light's slope-scaled one and the settings' constant one.
struct RasterBias {
    float slopeScale;
    float constant;
};

// The casters a tile draws, culled by `casters`; none where the GPU culls them (no hierarchy).
std::vector<std::uint32_t> tileCasterList(const CasterBvh* casters, const CasterVolume& volume)
{
    return casters ? casters->inFrustum(volume) : std::vector<std::uint32_t>();
}

LocalShadowView shadowView(const glm::mat4& view, float fov, float nearPlane, float range, RasterBias bias,
                           const rhi::Conventions& conventions, const CasterBvh* casters)
{
    const glm::mat4 projection = conventions.perspective(fov, 1.0f, nearPlane, range);
    const CasterVolume volume = frustumVolume(view, fov, nearPlane, range);
    return {projection, projection * view, bias.slopeScale, bias.constant, tileCasterList(casters, volume), {}, volume};
}

// The normal offset's reach per unit of distance, `scale`, goes to the lit pass's lookups on the receiver side and
// to the caster pass's vertices (with the light at `position`) on the caster side; returns the lit pass's share.
float sideOfNormalBias(LocalShadowView& view, NormalBiasSide side, float scale, glm::vec3 position)
{
    if (side == NormalBiasSide::Receiver)
        return scale;
    view.normalOffset = {scale, glm::vec4(position, 1.0f)};
    return 0.0f;
}

// What the soft filters need of a light's projection: the filter, its depth row (perspectiveDistance), the light's
// radius in texels at unit distance (lightTexels) and the near plane.
struct SoftProjection {
    ShadowFilter filter;
    PerspectiveTileSoft tileSoft;
};

SoftProjection softProjection(ShadowFilter filter, const glm::mat4& projection, std::uint32_t tileSize,
                              float sourceRadius, float nearPlane, const rhi::Conventions& conventions)
{
    return {filter, perspectiveTileSoft(projection, tileSize, sourceRadius, nearPlane, conventions)};
}

// A tile of `size` texels whose top-left texel is `offset`.
struct TilePlace {
    glm::uvec2 offset;
    std::uint32_t size;
};

void addTile(LocalShadowPlan& plan, TilePlace place, LocalShadowView view, float normalBiasScale,
             const SoftProjection& soft, const rhi::Conventions& conventions)
{
    const auto tile = static_cast<std::uint32_t>(plan.tiles.size());
    const glm::ivec2 first(place.offset);
    plan.tileData.push_back(
        {.worldToAtlas = worldToAtlas(view.viewProjection, place.offset, place.size, plan.atlasSize, conventions),
         .bounds = {first, first + static_cast<int>(place.size - 1)},
         .soft = soft.tileSoft,
         .normalBias = normalBiasScale,
         .shadowFilter = soft.filter});
    const auto size = static_cast<float>(place.size);
    plan.tiles.push_back(
        {std::move(view), tile, {static_cast<float>(first.x), static_cast<float>(first.y), size, size}});
}

void planSpot(LocalShadowPlan& plan, const LocalShadowSettings& local, const SpotShadowInput& spot,
              const PackedLight& packed, const rhi::Conventions& conventions, const CasterBvh* casters)
{
    const ShadowFilter filter = spot.filter.value_or(local.filter);
    const float fov = spotFieldOfView(spot.outerAngle, packed.size, filter, spot.normalBias, local.spotFovBias);
    const float nearPlane = localShadowNearPlane(spot.range, spot.nearPlane, local);
    const glm::mat4 projection = conventions.perspective(fov, 1.0f, nearPlane, spot.range);
    const float bias = localNormalBiasScale(projection, packed.size, filter, spot.normalBias);
    LocalShadowView view = shadowView(spotView(spot.position, spot.direction), fov, nearPlane, spot.range,
                                      {spot.slopeScaleBias, local.depthBias}, conventions, casters);
    const float receiverBias = sideOfNormalBias(view, spot.normalBiasSide, bias, spot.position);
    addTile(plan, {packed.offsets.front(), packed.size}, std::move(view), receiverBias,
            softProjection(filter, projection, packed.size, spot.sourceRadius, nearPlane, conventions), conventions);
}

void planPointTiles(LocalShadowPlan& plan, const LocalShadowSettings& local, const PointShadowInput& point,
                    const PackedLight& packed, const rhi::Conventions& conventions, const CasterBvh* casters)
{
    const ShadowFilter filter = point.filter.value_or(local.filter);
    const float fov = pointFaceFieldOfView(packed.size, filter, point.normalBias);
    const float nearPlane = localShadowNearPlane(point.range, point.nearPlane, local);
    const glm::mat4 projection = conventions.perspective(fov, 1.0f, nearPlane, point.range);
    const float bias = localNormalBiasScale(projection, packed.size, filter, point.normalBias);
    const SoftProjection soft =
        softProjection(filter, projection, packed.size, point.sourceRadius, nearPlane, conventions);
    for (std::uint32_t face = 0; face < cubeFaceCount; ++face) {
        LocalShadowView view = shadowView(pointFaceView(static_cast<CubeFace>(face), point.position), fov, nearPlane,
                                          point.range, {point.slopeScaleBias, local.depthBias}, conventions, casters);
        const float receiverBias = sideOfNormalBias(view, point.normalBiasSide, bias, point.position);
        addTile(plan, {packed.offsets[face], packed.size}, std::move(view), receiverBias, soft, conventions);
    }
}

// CubeMap mode: the six mirrored face views of the hardware cube layout (rhi::cubeFaceView), 90 degrees each.
void planCube(LocalShadowPlan& plan, const LocalShadowSettings& local, const PointShadowInput& point,
              std::uint32_t pointIndex, const rhi::Conventions& conventions, const CasterBvh& casters)
{
    constexpr float kRightAngle = 1.57079633f;
    const float nearPlane = localShadowNearPlane(point.range, point.nearPlane, local);
    const glm::mat4 projection = rhi::cubeFaceProjection(conventions, nearPlane, point.range);
    // Window depth of major-axis distance z is (a * -z + b) / z: the projection's depth row through clipToTexture.
    const glm::mat4 toTexture = conventions.clipToTexture() * projection;
    const ShadowFilter filter = point.filter.value_or(local.filter);
    const float bias = localNormalBiasScale(projection, local.cubeMapSize, filter, point.normalBias);
    LocalShadowCube& shadowCube = plan.uniforms.cubes[plan.cubes.size()];
    shadowCube.shadowFilter = filter;
    shadowCube.lightTexels = point.sourceRadius / std::abs(texelSizeAtUnitDistance(projection, local.cubeMapSize));
    shadowCube.nearPlane = nearPlane;
    ShadowCube cube;
    cube.lightIndex = pointIndex;
    float receiverBias = bias;
    for (const CubeFace face : rhi::allCubeFaces) {
        const glm::mat4 view = rhi::cubeFaceView(face, point.position);
        LocalShadowView& faceView = cube.faces[static_cast<std::size_t>(face)];
        const CasterVolume volume = frustumVolume(view, kRightAngle, nearPlane, point.range);
        faceView = {projection, projection * view, point.slopeScaleBias, local.depthBias, casters.inFrustum(volume), {},
                    volume};
        receiverBias = sideOfNormalBias(faceView, point.normalBiasSide, bias, point.position);
    }
    shadowCube.depthRow = {toTexture[2][2], toTexture[3][2]};
    shadowCube.normalBias = receiverBias;
    shadowCube.invFaceSize = 1.0f / static_cast<float>(local.cubeMapSize);
    plan.cubes.push_back(std::move(cube));
}

} // namespace

std::vector<std::uint32_t> cullCastersInFrustum(const glm::mat4& view, float fov, float nearPlane, float farPlane,
                                                std::span<const Bounds> casterBounds)
{
    const CasterVolume volume = frustumVolume(view, fov, nearPlane, farPlane);
    std::vector<std::uint32_t> inside;
    for (std::uint32_t i = 0; i < casterBounds.size(); ++i)
        if (meetsFrustum(casterBounds[i], volume))
            inside.push_back(i);
    return inside;
}

LocalShadowPlan planLocalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                 const ShadowCamera& camera, std::span<const SpotShadowInput> spots,
                                 std::span<const PointShadowInput> points, std::span<const Bounds> casterBounds,
                                 const LocalAtlasAllocation& previous)
{
    validate(settings);
    const LocalShadowSettings& local = settings.local;
    LocalShadowPlan plan;
    plan.atlasSize = local.atlasSize;
    plan.spotTiles.assign(spots.size(), -1);
    plan.pointShadows.assign(points.size(), -1);
    // Every light's culling walks one hierarchy of the casters' boxes, so that it costs what the light sees; a frame
    // without spot and point lights builds none.
    const CasterBvh casters(spots.empty() && points.empty() ? std::span<const Bounds>() : casterBounds);
    std::vector<Candidate> candidates;
    std::vector<std::uint32_t> cubes; // point light indices, CubeMap mode
    for (std::uint32_t i = 0; i < spots.size(); ++i) {
        const SpotShadowInput& spot = spots[i];
        const bool anyCaster =
            casters.anyInFrustum(frustumVolume(spotView(spot.position, spot.direction), 2.0f * spot.outerAngle,
                                               localShadowNearPlane(spot.range, spot.nearPlane, local), spot.range));
        if (wantsShadow(plan, LightKind::Spot, i, spot.strength,
                        shadowsNothing({spot.position, spot.range, anyCaster}, camera, settings.maxDistance)))
            candidates.push_back(
                {LightKind::Spot,
                 i,
                 {.position = spot.position, .range = spot.range, .shadowResolution = spot.shadowResolution},
                 spot.intensity});
    }
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const PointShadowInput& point = points[i];
        const bool anyCaster = casters.anyInRange(point.position, point.range);
        if (!wantsShadow(plan, LightKind::Point, i, point.strength,
                         shadowsNothing({point.position, point.range, anyCaster}, camera, settings.maxDistance)))
            continue;
        if (local.pointMode == PointShadowMode::Atlas) {
            candidates.push_back(
                {LightKind::Point,
                 i,
                 {.position = point.position, .range = point.range, .shadowResolution = point.shadowResolution},
                 point.intensity});
        } else if (cubes.size() == maxShadowCubes) {
            plan.report.push_back(
                {LightKind::Point, i, fmt::format("all {} shadow cube maps are taken", maxShadowCubes)});
        } else {
            plan.pointShadows[i] = static_cast<int>(cubes.size());
            cubes.push_back(i);
        }
    }

    const std::vector<ShadowTileRequest> requests = tileRequests(candidates, local, camera);
    const ShadowAtlasPackerSettings packing = packerSettings(local);
    ShadowAtlasPacker packer =
        previous.packer == packing ? ShadowAtlasPacker(packing, previous.pack.lights) : ShadowAtlasPacker(packing);
    plan.allocation = {packing, packer.pack(requests)};
    const ShadowAtlasPack& pack = plan.allocation.pack;
    // Atlas tiles culled on the GPU list no casters here (their views keep the volume); cube faces are culled here.
    const CasterBvh* tileCasters = culledOnGpu(settings) ? nullptr : &casters;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        const Candidate& candidate = candidates[c];
        const PackedLight& packed = pack.lights[c];
        const auto note = std::find_if(pack.notes.begin(), pack.notes.end(),
                                       [&](const ShadowAtlasPackNote& n) { return n.lightId == packed.lightId; });
        if (packed.size == 0) {
            plan.report.push_back({candidate.kind, candidate.lightIndex, note->reason});
            continue;
        }
        if (note != pack.notes.end())
            plan.lowered.push_back({candidate.kind, candidate.lightIndex, note->reason});
        const int first = static_cast<int>(plan.tiles.size());
        if (candidate.kind == LightKind::Spot) {
            plan.spotTiles[candidate.lightIndex] = first;
            planSpot(plan, local, spots[candidate.lightIndex], packed, conventions, tileCasters);
        } else {
            plan.pointShadows[candidate.lightIndex] = first;
            planPointTiles(plan, local, points[candidate.lightIndex], packed, conventions, tileCasters);
        }
    }

    for (const std::uint32_t pointIndex : cubes)
        planCube(plan, local, points[pointIndex], pointIndex, conventions, casters);

    plan.uniforms.atlasSize = static_cast<float>(local.atlasSize);
    plan.uniforms.defaultFilter = local.filter;
    plan.uniforms.pointMode = local.pointMode;
    plan.uniforms.soft = softShadowUniforms(settings.soft);
    return plan;
}

} // namespace penumbra::shadows
