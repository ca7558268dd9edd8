#include "penumbra/truth/RayCaster.hpp"

#include "Bvh.hpp"
#include "MollerTrumbore.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra::truth {
namespace {

// Triangles are stored as the intersection test wants them.
struct TriangleEdges {
    glm::vec3 v0;
    glm::vec3 e1;
    glm::vec3 e2;
};

struct TriangleSource {
    std::uint32_t object;
    std::uint32_t triangle;
};

// An object whose surface has holes: blocks a ray only where its alpha reaches `threshold`.
// Textured materials keep a copy of their texture: the caster outlives the scene.
struct AlphaTest {
    scene::Material material;
    float threshold;
    std::optional<scene::TextureImage> texture;
};

std::optional<AlphaTest> alphaTestFor(const scene::Scene& scene, const scene::Material& material, RayKind kind)
{
    std::optional<scene::TextureImage> texture;
    const std::optional<scene::MaterialTexture>& baseColor = material.texture(scene::TextureSlot::BaseColor);
    if (baseColor && material.caster != scene::CasterMode::On && material.caster != scene::CasterMode::Off)
        texture = scene.textures.at(baseColor->image);
    switch (material.caster) {
    case scene::CasterMode::Clip:
        return AlphaTest{material, material.alphaCutoff, std::move(texture)};
    case scene::CasterMode::Dither:
        if (kind == RayKind::Shadow)
            return AlphaTest{material, kDitherShadowThreshold, std::move(texture)};
        return std::nullopt;
    case scene::CasterMode::On:
    case scene::CasterMode::Off:
        return std::nullopt;
    }
    return std::nullopt;
}

bool isSeen(const scene::Scene& scene, const scene::Object& object, RayKind kind)
{
    return kind == RayKind::Camera ? object.castShadows != scene::ShadowCasting::ShadowsOnly
                                   : scene.castsShadows(object);
}

// The side of an object's triangles that the passes draw, as the sign that dot(front normal, ray direction)
// must have (0: both sides). The lit pass culls back faces of single-sided materials; the shadow pass draws
// the light-facing side of single-sided casters, and a shadow ray travels towards the light, so it meets
// that side from behind.
float drawnSide(const scene::Scene& scene, const scene::Object& object, RayKind kind)
{
    const bool doubleSided = scene.materialOf(object).doubleSided;
    if (kind == RayKind::Camera)
        return doubleSided ? 0.0f : -1.0f;
    return doubleSided || object.castShadows == scene::ShadowCasting::TwoSided ? 0.0f : 1.0f;
}

struct PreparedRay {
    glm::vec3 origin;
    glm::vec3 direction;
    glm::vec3 inverseDirection;
};

PreparedRay prepare(const glm::vec3& origin, const glm::vec3& direction)
{
    const glm::vec3 d = glm::normalize(direction);
    // A zero component would give 0 * inf = NaN in the slab test for origins on a slab plane;
    // a tiny stand-in gives the same answer without NaN.
    constexpr float kTiny = 1e-20f;
    const auto safe = [](float c) { return std::abs(c) > kTiny ? c : std::copysign(kTiny, c); };
    return {origin, d, 1.0f / glm::vec3(safe(d.x), safe(d.y), safe(d.z))};
}

constexpr float kNoEntry = std::numeric_limits<float>::infinity();

// Distance at which the ray enters the node's box within [0, maxDistance], or kNoEntry.
// The exit distance is scaled up by 1 + 2 * gamma(3) (Ize, "Robust BVH ray traversal"), so
// rounding never drops a box that a triangle inside it is hit in.
float boxEntry(const BvhNode& node, const PreparedRay& ray, float maxDistance)
{
    const glm::vec3 t0 = (node.min - ray.origin) * ray.inverseDirection;
    const glm::vec3 t1 = (node.max - ray.origin) * ray.inverseDirection;
    const glm::vec3 tNear = glm::min(t0, t1);
    const glm::vec3 tFar = glm::max(t0, t1);
    const float enter = std::max(std::max(tNear.x, tNear.y), std::max(tNear.z, 0.0f));
    const float exit = std::min(std::min(tFar.x, tFar.y), tFar.z) * 1.00000024f;
    return enter <= exit && enter <= maxDistance ? enter : kNoEntry;
}

} // namespace

struct RayCaster::Data {
    RayKind kind;
    std::vector<BvhNode> nodes;
    // Per triangle, in BVH leaf order.
    std::vector<TriangleEdges> triangles;
    std::vector<TriangleSource> sources;
    std::vector<std::array<glm::vec2, 3>> uvs;
    // Per scene object.
    std::vector<std::optional<AlphaTest>> alphaTests;
    std::vector<float> drawnSides;

    bool drawnSideFaces(std::uint32_t index, const PreparedRay& ray) const
    {
        const TriangleEdges& t = triangles[index];
        return drawnSides[sources[index].object] * glm::dot(glm::cross(t.e1, t.e2), ray.direction) >= 0.0f;
    }

    // The alpha of an alpha-tested triangle at a hit.
    float alpha(const AlphaTest& test, std::uint32_t index, glm::vec2 barycentrics) const
    {
        const std::array<glm::vec2, 3>& uv = uvs[index];
        const glm::vec2 at =
            (1.0f - barycentrics.x - barycentrics.y) * uv[0] + barycentrics.x * uv[1] + barycentrics.y * uv[2];
        return scene::materialAlpha(test.material, at, test.texture ? &*test.texture : nullptr);
    }

    // Whether a hit on triangle `index` stops the ray: the drawn side, and not in a hole.
    bool blocks(std::uint32_t index, const PreparedRay& ray, glm::vec2 barycentrics) const
    {
        if (!drawnSideFaces(index, ray))
            return false;
        const std::optional<AlphaTest>& test = alphaTests[sources[index].object];
        return !test || alpha(*test, index, barycentrics) >= test->threshold;
    }

    // Visits the triangles of every leaf the ray reaches within maxDistance, nearer boxes
    // first. visit(triangle, maxDistance) may shorten maxDistance and returns true to stop.
    template <typename Visit>
    void traverse(const PreparedRay& ray, float maxDistance, Visit&& visit) const
    {
        if (nodes.empty() || boxEntry(nodes[0], ray, maxDistance) == kNoEntry)
            return;
        struct Pending {
            std::uint32_t node;
            float entry;
        };
        std::array<Pending, kBvhMaxDepth + 1> stack;
        std::size_t size = 0;
        std::uint32_t current = 0;
        while (true) {
            const BvhNode& node = nodes[current];
            if (node.count == 0) {
                const float left = boxEntry(nodes[node.first], ray, maxDistance);
                const float right = boxEntry(nodes[node.first + 1], ray, maxDistance);
                if (left != kNoEntry || right != kNoEntry) {
                    const bool leftFirst = left <= right;
                    if (left != kNoEntry && right != kNoEntry)
                        stack[size++] = leftFirst ? Pending{node.first + 1, right} : Pending{node.first, left};
                    current = leftFirst ? node.first : node.first + 1;
                    continue;
                }
            } else {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    if (visit(i, maxDistance))
                        return;
                }
            }
            // Next pending node that is still nearer than the nearest hit so far.
            do {
                if (size == 0)
                    return;
                --size;
            } while (stack[size].entry > maxDistance);
            current = stack[size].node;
        }
    }
};

RayCaster::RayCaster(const scene::Scene& scene, RayKind kind) : data_(std::make_unique<Data>())
{
    scene.validate();
    data_->kind = kind;
    std::vector<TriangleEdges> triangles;
    std::vector<TriangleSource> sources;
    std::vector<std::array<glm::vec2, 3>> uvs;
    std::vector<scene::Bounds> bounds;
    for (std::uint32_t objectIndex = 0; objectIndex < scene.objects.size(); ++objectIndex) {
        const scene::Object& object = scene.objects[objectIndex];
        const scene::Material& material = scene.materialOf(object);
        data_->alphaTests.push_back(alphaTestFor(scene, material, kind));
        data_->drawnSides.push_back(drawnSide(scene, object, kind));
        if (!isSeen(scene, object, kind))
            continue;
        const scene::MeshData& mesh = scene.meshOf(object);
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            std::array<glm::vec3, 3> world;
            std::array<glm::vec2, 3> uv;
            scene::Bounds triangleBounds;
            for (std::size_t k = 0; k < 3; ++k) {
                const scene::Vertex& vertex = mesh.vertices[mesh.indices[3 * t + k]];
                world[k] = glm::vec3(object.transform * glm::vec4(vertex.position, 1.0f));
                // Where the passes read the base colour texture (its uv set and transform, affine, so it may be
                // applied before the barycentric interpolation).
                uv[k] = scene::textureUv(material.texture(scene::TextureSlot::BaseColor), vertex.uv, vertex.uv1);
                triangleBounds.extend(world[k]);
            }
            triangles.push_back({world[0], world[1] - world[0], world[2] - world[0]});
            sources.push_back({objectIndex, t});
            uvs.push_back(uv);
            bounds.push_back(triangleBounds);
        }
    }
    Bvh bvh = buildBvh(bounds);
    data_->nodes = std::move(bvh.nodes);
    data_->triangles.reserve(triangles.size());
    data_->sources.reserve(triangles.size());
    data_->uvs.reserve(triangles.size());
    for (const std::uint32_t index : bvh.order) {
        data_->triangles.push_back(triangles[index]);
        data_->sources.push_back(sources[index]);
        data_->uvs.push_back(uvs[index]);
    }
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

RayKind RayCaster::kind() const { return data_->kind; }

std::uint32_t RayCaster::triangleCount() const { return static_cast<std::uint32_t>(data_->triangles.size()); }

bool RayCaster::occluded(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const
{
    const PreparedRay ray = prepare(origin, direction);
    bool found = false;
    data_->traverse(ray, maxDistance, [&](std::uint32_t i, float& limit) {
        const TriangleEdges& t = data_->triangles[i];
        const std::optional<TriangleHit> hit =
            detail::intersectEdges(ray.origin, ray.direction, t.v0, t.e1, t.e2, limit);
        found = hit && data_->blocks(i, ray, hit->barycentrics);
        return found;
    });
    return found;
}

Occlusion RayCaster::occlusion(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const
{
    const PreparedRay ray = prepare(origin, direction);
    Occlusion result;
    data_->traverse(ray, maxDistance, [&](std::uint32_t i, float& limit) {
        const TriangleEdges& t = data_->triangles[i];
        const std::optional<TriangleHit> hit =
            detail::intersectEdges(ray.origin, ray.direction, t.v0, t.e1, t.e2, limit);
        if (!hit)
            return false;
        const std::optional<AlphaTest>& test = data_->alphaTests[data_->sources[i].object];
        // Only shadow rays alpha-test dithered casters; occlusion() reports their alpha apart.
        if (!test || test->material.caster != scene::CasterMode::Dither) {
            result.solid = data_->blocks(i, ray, hit->barycentrics);
            return result.solid;
        }
        if (data_->drawnSideFaces(i, ray))
            result.ditherCoverage = std::max(result.ditherCoverage, data_->alpha(*test, i, hit->barycentrics));
        return false;
    });
    return result;
}

std::optional<Hit> RayCaster::closestHit(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const
{
    const PreparedRay ray = prepare(origin, direction);
    std::optional<TriangleHit> best;
    std::uint32_t bestIndex = 0;
    data_->traverse(ray, maxDistance, [&](std::uint32_t i, float& limit) {
        const TriangleEdges& t = data_->triangles[i];
        const std::optional<TriangleHit> hit =
            detail::intersectEdges(ray.origin, ray.direction, t.v0, t.e1, t.e2, limit);
        if (hit && data_->blocks(i, ray, hit->barycentrics)) {
            best = hit;
            bestIndex = i;
            limit = hit->distance;
        }
        return false;
    });
    if (!best)
        return std::nullopt;
    const TriangleEdges& t = data_->triangles[bestIndex];
    const TriangleSource& source = data_->sources[bestIndex];
    return Hit{best->distance, source.object, source.triangle, best->barycentrics,
               glm::normalize(glm::cross(t.e1, t.e2))};
}

} // namespace penumbra::truth
