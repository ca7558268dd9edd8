#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <glm/vec2.hpp>
#include <span>

namespace penumbra::shadows {

// Weights of consecutive texels first .. first + count - 1 along one axis (texel i spans [i, i + 1)
// in texel space, centre i + 0.5) for a filter centred at texel-space position `centre`.
struct TexelWeights {
    int first = 0;
    int count = 0;
    std::array<float, 8> weights{};
};

// PCF2x2: the bilinear weights (area of a 1-texel box over each texel). PCF NxN: area of a tent
// N texels wide over each texel, normalised; it spans the N + 1 texels round(centre) +- (N + 1) / 2.
TexelWeights tentTexelWeights(ShadowFilter filter, float centre);

// One bilinear depth-comparison tap at texture coordinate uv.
struct ShadowTap {
    glm::vec2 uv{0.0f};
    float weight = 0.0f;
};

// The bilinear taps of a tent filter.
struct ShadowTaps {
    std::array<ShadowTap, 16> taps{};
    int count = 0;

    // The taps in use.
    std::span<const ShadowTap> view() const { return {taps.data(), static_cast<std::size_t>(count)}; }
};

// The taps of a filter at texture coordinate uv (the same math as the SampleShadow_ComputeSamples_Tent
// functions): 1, 4, 9 or 16 taps. Each tap merges two neighbouring texel weights a, b per axis into one
// bilinear read placed b / (a + b) past the first texel's centre, with weight a + b, so that
// sum(weight * bilinear comparison) equals the per-texel tent exactly. Weights sum to 1.
ShadowTaps tentFilterTaps(ShadowFilter filter, glm::vec2 uv, glm::vec2 textureSize);

} // namespace penumbra::shadows
