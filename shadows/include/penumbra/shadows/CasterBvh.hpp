#pragma once

#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CasterVolume.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::shadows {

// A bounding volume hierarchy over the casters' world boxes, built once per frame, so that each light's culling costs
// what the light sees rather than every caster: a node is skipped when its box lies wholly outside one plane of the
// frustum (or beyond a sphere), which puts every box below it outside as well (the half-space is convex). The leaves
// are tested with the planner's own rules (meetsFrustum, the range test), so the lists are exactly the brute-force
// ones; a node is skipped only with a margin far above float rounding, so rounding cannot make them differ.
// Median split on the longest axis of the boxes' centres (Ericson, "Real-Time Collision Detection", 6.2.1, top-down
// construction).
class CasterBvh {
public:
    explicit CasterBvh(std::span<const Bounds> boxes);

    // The boxes that meetsFrustum(box, volume) accepts, ascending: cullCastersInFrustum's list. `volume` must be a
    // frustum (frustumVolume) whose view is a rigid transform.
    std::vector<std::uint32_t> inFrustum(const CasterVolume& volume) const;
    // Whether any box meets the frustum: !inFrustum(volume).empty(), stopping at the first.
    bool anyInFrustum(const CasterVolume& volume) const;
    // Whether any box comes within `radius` of `centre`: castersInRange's answer.
    bool anyInRange(glm::vec3 centre, float radius) const;

    std::size_t size() const { return boxes_.size(); }

private:
    struct Node {
        Bounds box;
        glm::vec3 centre{0.0f}; // the box's centre
        glm::vec3 reach{0.0f}; // its half size, plus the skipping margin for its coordinates' magnitude
        std::uint32_t first = 0; // a leaf's first entry in order_, or an inner node's second child (the first follows)
        std::uint32_t count = 0; // a leaf's boxes; 0 for an inner node
    };

    std::uint32_t build(std::uint32_t first, std::uint32_t count);
    template <typename Skip, typename Visit>
    bool walk(const Skip& skip, const Visit& visit) const;

    std::span<const Bounds> boxes_;
    std::vector<std::uint32_t> order_; // box indices, grouped by leaf
    std::vector<Node> nodes_; // depth first, the root first
};

} // namespace penumbra::shadows
