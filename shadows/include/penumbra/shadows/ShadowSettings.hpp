#pragma once

#include "penumbra/rhi/Format.hpp"

#include <cstdint>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// Percentage-closer filter of directional shadows: a tent N texels wide (2x2 is one bilinear tap).
enum class ShadowFilter { PCF2x2, PCF3x3, PCF5x5, PCF7x7 };

// How the lit shader moves from one cascade to the next.
enum class CascadeBlend { Hard, Soft, Dither };

// Width of the filter's kernel in texels: 2, 3, 5, 7.
int filterSize(ShadowFilter filter);

// The "filter size" of Catlike Coding's "Directional Shadows" tutorial (section "Shadow Quality")
// for the normal bias and the culling-sphere shrink:
// enum + 1 = 1, 2, 3, 4 texels (texel size x this x sqrt 2 is the normal bias), not the kernel width.
float normalBiasFilterFactor(ShadowFilter filter);

// Bilinear comparison taps the filter takes: 1, 4, 9, 16.
int filterTapCount(ShadowFilter filter);

struct DirectionalShadowSettings {
    std::uint32_t atlasSize = 1024;            // texels per side, a power of two in 256..8192
    ShadowFilter filter = ShadowFilter::PCF2x2;
    std::uint32_t cascadeCount = 4;            // 1..4
    glm::vec3 cascadeRatios{0.1f, 0.25f, 0.5f}; // ends of cascades 1..3 as fractions of the shadow distance
    float cascadeFade = 0.1f;                  // 0.001..1, fraction of the last cascade's radius that fades
    CascadeBlend cascadeBlend = CascadeBlend::Hard;
    rhi::Format atlasFormat = rhi::Format::D32F; // D16, D24S8 or D32F
};

// Where point lights keep their six faces.
enum class PointShadowMode {
    Atlas,   // six tiles of the other atlas, the face picked in the lit shader (Catlike Coding's "Point and Spot Shadows")
    CubeMap, // a depth cube map per light, sampled with hardware cube lookups
};

// Spot and point shadows: the second atlas of up to 16 tiles (a spot light takes one, a point light six).
struct OtherShadowSettings {
    std::uint32_t atlasSize = 1024; // texels per side, a power of two in 256..8192
    ShadowFilter filter = ShadowFilter::PCF2x2;
    rhi::Format atlasFormat = rhi::Format::D32F; // D16, D24S8 or D32F
    PointShadowMode pointMode = PointShadowMode::Atlas;
    std::uint32_t cubeMapSize = 512; // CubeMap mode: texels per face side, a power of two in 64..4096
};

struct ShadowSettings {
    float maxDistance = 100.0f; // view depth beyond which nothing is shadowed, > 0.001; applies to every light
    float distanceFade = 0.1f;  // 0.001..1, fraction of maxDistance over which shadows fade out
    DirectionalShadowSettings directional;
    OtherShadowSettings other;
};

// Throws rhi::Error "<field>: <value> is out of range, allowed <range>" for the first field out of range
// (field paths as in JSON: "directional.cascadeCount").
void validate(const ShadowSettings& settings);

} // namespace penumbra::shadows
