#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <span>

namespace penumbra::shadows {

// A Poisson disk of `count` points (16, 32 or 64: kPoissonSampleCounts) in the unit disk, built by Mitchell's
// best-candidate algorithm (Mitchell 1991, "Spectrally Optimal Sampling for Distribution Ray Tracing") from a fixed
// seed, so the same points every run and on every backend (the lit shader gets them as constants). Throws
// rhi::Error for another count.
std::span<const glm::vec2> poissonDisk(std::uint32_t count);

} // namespace penumbra::shadows
