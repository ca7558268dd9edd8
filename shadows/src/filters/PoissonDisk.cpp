#include "penumbra/shadows/PoissonDisk.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace penumbra::shadows {
namespace {

std::vector<glm::vec2> spiral(std::uint32_t count)
{
    std::vector<glm::vec2> points;
    for (std::uint32_t k = 0; k < count; ++k) {
        const float radius = std::sqrt((static_cast<float>(k) + 0.5f) / static_cast<float>(count));
        const float angle = kGoldenAngle * static_cast<float>(k);
        points.push_back(radius * glm::vec2(std::cos(angle), std::sin(angle)));
    }
    return points;
}

glm::vec2 mean(const std::vector<glm::vec2>& points)
{
    glm::vec2 sum{0.0f};
    for (const glm::vec2& p : points)
        sum += p;
    return sum / static_cast<float>(points.size());
}

struct Disk {
    std::uint32_t count;
    glm::vec2 spiralMean;
    std::vector<glm::vec2> points;
};

Disk centredDisk(std::uint32_t count)
{
    Disk disk{count, glm::vec2(0.0f), spiral(count)};
    disk.spiralMean = mean(disk.points);
    for (glm::vec2& p : disk.points)
        p -= disk.spiralMean;
    return disk;
}

const Disk& diskOf(std::uint32_t count)
{
    static const std::vector<Disk> disks = [] {
        std::vector<Disk> offered;
        for (const std::uint32_t offeredCount : kPoissonSampleCounts)
            offered.push_back(centredDisk(offeredCount));
        return offered;
    }();
    for (const Disk& disk : disks)
        if (disk.count == count)
            return disk;
    throw rhi::Error(fmt::format("Poisson disk: {} points, allowed 16, 32, 64", count));
}

} // namespace

std::span<const glm::vec2> poissonDisk(std::uint32_t count) { return diskOf(count).points; }

glm::vec2 spiralMean(std::uint32_t count) { return diskOf(count).spiralMean; }

} // namespace penumbra::shadows
