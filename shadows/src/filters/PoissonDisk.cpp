#include "penumbra/shadows/PoissonDisk.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace penumbra::shadows {
namespace {

// Candidates per placed point: Mitchell's k; 30 spreads points close to a maximal Poisson disk.
constexpr std::uint32_t kCandidatesPerPoint = 30;

// Knuth's MMIX linear congruential generator: integer arithmetic only, so the disk is the same everywhere.
class Lcg {
public:
    float next()
    {
        state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<float>(state_ >> 40) / static_cast<float>(1u << 24);
    }

private:
    std::uint64_t state_ = 0x9e3779b97f4a7c15ull;
};

glm::vec2 pointInDisk(Lcg& random)
{
    // Uniform over the disk's area: radius sqrt(u).
    const float radius = std::sqrt(random.next());
    const float angle = 6.28318531f * random.next();
    return {radius * std::cos(angle), radius * std::sin(angle)};
}

std::vector<glm::vec2> bestCandidateDisk(std::uint32_t count)
{
    Lcg random;
    std::vector<glm::vec2> points;
    points.push_back(pointInDisk(random));
    while (points.size() < count) {
        glm::vec2 best{0.0f};
        float bestDistance = -1.0f;
        for (std::uint32_t c = 0; c < kCandidatesPerPoint * points.size(); ++c) {
            const glm::vec2 candidate = pointInDisk(random);
            float nearest = std::numeric_limits<float>::max();
            for (const glm::vec2& p : points)
                nearest = std::min(nearest, glm::distance(candidate, p));
            if (nearest > bestDistance) {
                bestDistance = nearest;
                best = candidate;
            }
        }
        points.push_back(best);
    }
    return points;
}

// Best candidate puts too many points near the disk's rim: nothing lies beyond the rim to push them back in,
// so the 16-point disk's mean squared radius is 0.68 where a disk uniform over its area has 0.5, and a filter over it
// blurs as a disk 17% wider than its radius. Giving the k-th nearest of n points (k from 0) the radius sqrt((k + 0.5)
// / n), the radii of n strata of equal area, keeps the directions and the order of the radii (so the spacing) and
// makes the points uniform over the area, as a filter of that radius assumes.
std::vector<glm::vec2> withStratifiedRadii(std::vector<glm::vec2> points)
{
    std::vector<std::size_t> byRadius(points.size());
    for (std::size_t i = 0; i < byRadius.size(); ++i)
        byRadius[i] = i;
    std::sort(byRadius.begin(), byRadius.end(),
              [&](std::size_t a, std::size_t b) { return glm::length(points[a]) < glm::length(points[b]); });
    const float count = static_cast<float>(points.size());
    for (std::size_t k = 0; k < byRadius.size(); ++k) {
        glm::vec2& p = points[byRadius[k]];
        p *= std::sqrt((static_cast<float>(k) + 0.5f) / count) / glm::length(p);
    }
    return points;
}

glm::vec2 centroid(const std::vector<glm::vec2>& points)
{
    glm::vec2 sum{0.0f};
    for (const glm::vec2& p : points)
        sum += p;
    return sum / static_cast<float>(points.size());
}

// The disk turns by a random angle per receiver, so a disk whose points' mean lies off the centre (best candidate's
// 16 points: 0.11 of the radius) shifts its estimate by that much of the radius in a random direction: noise at
// every edge. Moving the points by minus their mean and stratifying the radii again converges to a centred,
// area-uniform disk; 32 rounds leave a mean under 1e-4 of the radius for every count.
std::vector<glm::vec2> centredUniformDisk(std::vector<glm::vec2> points)
{
    points = withStratifiedRadii(std::move(points));
    for (int round = 0; round < 32; ++round) {
        const glm::vec2 mean = centroid(points);
        for (glm::vec2& p : points)
            p -= mean;
        points = withStratifiedRadii(std::move(points));
    }
    return points;
}

} // namespace

std::span<const glm::vec2> poissonDisk(std::uint32_t count)
{
    static const std::array<std::vector<glm::vec2>, 3> disks{centredUniformDisk(bestCandidateDisk(16)),
                                                             centredUniformDisk(bestCandidateDisk(32)),
                                                             centredUniformDisk(bestCandidateDisk(64))};
    for (const std::vector<glm::vec2>& disk : disks)
        if (disk.size() == count)
            return disk;
    throw rhi::Error(fmt::format("Poisson disk: {} points, allowed 16, 32, 64", count));
}

PoissonDiskUniforms poissonDiskUniforms()
{
    PoissonDiskUniforms u;
    std::size_t next = 0;
    for (const std::uint32_t count : {16u, 32u, 64u})
        for (const glm::vec2& p : poissonDisk(count)) {
            glm::vec4& slot = u.points[next / 2];
            if (next % 2 == 0) {
                slot.x = p.x;
                slot.y = p.y;
            } else {
                slot.z = p.x;
                slot.w = p.y;
            }
            ++next;
        }
    return u;
}

} // namespace penumbra::shadows
