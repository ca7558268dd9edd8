#pragma once

#include <array>
#include <cstdint>
#include <glm/vec4.hpp>
#include <glm/vec2.hpp>
#include <span>

namespace penumbra::shadows {

// A Poisson disk of `count` points (16, 32 or 64: kPoissonSampleCounts) in the unit disk, built by Mitchell's
// best-candidate algorithm (Mitchell 1991, "Spectrally Optimal Sampling for Distribution Ray Tracing") from a fixed
// seed, so the same points every run and on every backend (the lit shader gets them as constants), then centred and
// given the radii of equal-area rings, so that a filter over them blurs as the uniform disk of its radius. Throws
// rhi::Error for another count.
std::span<const glm::vec2> poissonDisk(std::uint32_t count);

// The disks of 16, 32 and 64 points one after the other (disk n starts at n - 16), two points a vec4, as the lit
// shader's uniform block PoissonDisks reads them (std140). A uniform block rather than a constant array: the drivers'
// compilers turn a dynamically indexed constant array into long chains of selects.
inline constexpr std::uint32_t kPoissonDiskPoints = 16 + 32 + 64;
struct PoissonDiskUniforms {
    std::array<glm::vec4, kPoissonDiskPoints / 2> points{};
};
static_assert(sizeof(PoissonDiskUniforms) == 896);

PoissonDiskUniforms poissonDiskUniforms();

} // namespace penumbra::shadows
