#include "penumbra/shadows/CasterBvh.hpp"

#include <algorithm>
#include <array>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>

namespace penumbra::shadows {
namespace {

constexpr std::uint32_t kBvhLeafBoxes = 4;

// How far past a plane or a sphere a node must lie before it is skipped, per unit of the coordinates' magnitude:
// about 170 float epsilons, far above the rounding of one plane or distance evaluation (a few epsilons), so that a
// box under a skipped node is outside by the leaf test's own arithmetic too.
constexpr float kBvhMargin = 1e-5f;

Bounds unionOf(const Bounds& a, const Bounds& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

// A plane of the frustum in world space: a point c is outside where dot(normal, c) + offset > 0.
struct BvhPlane {
    glm::vec3 normal;
    float offset;
};

// meetsFrustum's six tests as world-space planes: with p = view * c and depth = -p.z, outside where depth < near,
// depth > far, p.x > depth * tx, -p.x > depth * tx, p.y > depth * ty, -p.y > depth * ty.
std::array<BvhPlane, 6> frustumPlanes(const CasterVolume& volume)
{
    const glm::mat4& v = volume.view;
    const auto row = [&](int i) { return BvhPlane{{v[0][i], v[1][i], v[2][i]}, v[3][i]}; };
    const BvhPlane x = row(0), y = row(1), z = row(2);
    const float tx = volume.frustum.x, ty = volume.frustum.w, nearPlane = volume.frustum.y, farPlane = volume.frustum.z;
    const auto add = [](BvhPlane a, float s, BvhPlane b) {
        return BvhPlane{a.normal + s * b.normal, a.offset + s * b.offset};
    };
    return {{{z.normal, z.offset + nearPlane},
             {-z.normal, -z.offset - farPlane},
             add(x, tx, z),
             add({-x.normal, -x.offset}, tx, z),
             add(y, ty, z),
             add({-y.normal, -y.offset}, ty, z)}};
}

// The node's reach: its half size, plus the margin times its coordinates' magnitude, which outsideAPlane takes as the
// margin's share that grows with the box.
glm::vec3 nodeReach(const Bounds& box)
{
    return 0.5f * (box.max - box.min) + kBvhMargin * glm::max(glm::abs(box.min), glm::abs(box.max));
}

// Whether a whole node lies outside one of the planes, by the margin: its corner nearest to the plane is outside by
// more than kBvhMargin * (1 + |normal| . magnitude + |offset|).
bool outsideAPlane(glm::vec3 centre, glm::vec3 reach, const std::array<BvhPlane, 6>& planes)
{
    for (const BvhPlane& plane : planes)
        if (glm::dot(plane.normal, centre) - glm::dot(glm::abs(plane.normal), reach) >
            kBvhMargin * (1.0f + std::abs(plane.offset)) - plane.offset)
            return true;
    return false;
}

// Whether the whole box lies farther than `radius` from `centre`, by the margin.
bool beyondRange(const Bounds& box, glm::vec3 centre, float radius)
{
    const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
    const glm::vec3 magnitude = glm::max(glm::max(glm::abs(box.min), glm::abs(box.max)), glm::abs(centre));
    const float reach = radius + kBvhMargin * (1.0f + magnitude.x + magnitude.y + magnitude.z);
    return glm::dot(nearest - centre, nearest - centre) > reach * reach;
}

// castersInRange's test of one box.
bool boxInRange(const Bounds& box, glm::vec3 centre, float radius)
{
    const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
    return glm::dot(nearest - centre, nearest - centre) <= radius * radius;
}

} // namespace

CasterBvh::CasterBvh(std::span<const Bounds> boxes) : boxes_(boxes), order_(boxes.size())
{
    std::iota(order_.begin(), order_.end(), 0u);
    if (!boxes.empty()) {
        nodes_.reserve(2 * (boxes.size() / kBvhLeafBoxes + 1));
        build(0, static_cast<std::uint32_t>(boxes.size()));
    }
}

std::uint32_t CasterBvh::build(std::uint32_t first, std::uint32_t count)
{
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    Bounds box = boxes_[order_[first]];
    Bounds centres{box.min + box.max, box.min + box.max};
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Bounds& b = boxes_[order_[k]];
        box = unionOf(box, b);
        centres = unionOf(centres, {b.min + b.max, b.min + b.max});
    }
    nodes_.push_back({box, 0.5f * (box.min + box.max), nodeReach(box), first, count});
    if (count <= kBvhLeafBoxes)
        return index;
    const glm::vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    const auto begin = order_.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
        return boxes_[a].min[axis] + boxes_[a].max[axis] < boxes_[b].min[axis] + boxes_[b].max[axis];
    });
    build(first, half);
    const std::uint32_t second = build(first + half, count - half);
    nodes_[index].first = second;
    nodes_[index].count = 0;
    return index;
}

// Visits the boxes under every node that `skip` keeps, until `visit` returns true; returns whether it did.
template <typename Skip, typename Visit>
bool CasterBvh::walk(const Skip& skip, const Visit& visit) const
{
    if (nodes_.empty())
        return false;
    std::array<std::uint32_t, 64> stack{};
    std::size_t depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
        const std::uint32_t n = stack[--depth];
        const Node& node = nodes_[n];
        if (skip(node))
            continue;
        if (node.count == 0) {
            stack[depth++] = node.first;
            stack[depth++] = n + 1;
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
            if (visit(order_[k]))
                return true;
    }
    return false;
}

std::vector<std::uint32_t> CasterBvh::inFrustum(const CasterVolume& volume) const
{
    const std::array<BvhPlane, 6> planes = frustumPlanes(volume);
    std::vector<std::uint32_t> inside;
    walk([&](const Node& node) { return outsideAPlane(node.centre, node.reach, planes); },
         [&](std::uint32_t i) {
             if (meetsFrustum(boxes_[i], volume))
                 inside.push_back(i);
             return false;
         });
    std::sort(inside.begin(), inside.end());
    return inside;
}

bool CasterBvh::anyInFrustum(const CasterVolume& volume) const
{
    const std::array<BvhPlane, 6> planes = frustumPlanes(volume);
    return walk([&](const Node& node) { return outsideAPlane(node.centre, node.reach, planes); },
                [&](std::uint32_t i) { return meetsFrustum(boxes_[i], volume); });
}

bool CasterBvh::anyInRange(glm::vec3 centre, float radius) const
{
    return walk([&](const Node& node) { return beyondRange(node.box, centre, radius); },
                [&](std::uint32_t i) { return boxInRange(boxes_[i], centre, radius); });
}

} // namespace penumbra::shadows
