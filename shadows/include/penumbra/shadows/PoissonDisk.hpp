#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <span>

namespace penumbra::shadows {

// The sample disks of the Poisson-disk filters (16, 32 or 64 points: kPoissonSampleCounts): Vogel's golden-angle
// spiral (Vogel 1979, "A better way to construct the sunflower head"). Point k of n lies at radius sqrt((k + 0.5) / n),
// the radii of n rings of equal area, so a filter over the disk blurs as the uniform disk of its radius, and at
// angle k times the golden angle, so neighbours keep 1.55 / sqrt(n) apart (0.81 of the densest packing): a Poisson
// disk without a random seed. The spiral's mean lies off the centre (0.03 of the radius for 16 points); the disk is
// moved by minus it, as a turning disk whose mean lies off the centre shifts every estimate by that much.
// The shaders walk the spiral instead of reading a table: each tap turns the last one's direction by the golden
// angle (soft_shadows.glsl, DiskWalk), so a tap costs neither a uniform read nor a sine, which on Mesa's llvmpipe
// cost as much as its texture read.
inline constexpr float kGoldenAngle = 2.39996323f; // pi (3 - sqrt 5)

// The centred disk of `count` points. Throws rhi::Error for a count not in kPoissonSampleCounts.
std::span<const glm::vec2> poissonDisk(std::uint32_t count);

// The mean of the spiral's `count` points before centring: what the shaders' walk subtracts.
glm::vec2 spiralMean(std::uint32_t count);

} // namespace penumbra::shadows
