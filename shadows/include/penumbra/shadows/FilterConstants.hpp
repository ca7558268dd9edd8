#pragma once

#include <string>

namespace penumbra::shadows {

// The GLSL include "shadow_constants.glsl" of the lit shader: the ShadowFilter values, their kernel sizes and the
// Poisson disks' spiral (PoissonDisk.hpp), so that every number is written once, in C++.
//   PENUMBRA_FILTER_<NAME>          ShadowFilter values (PCF2X2 .. PCSS)
//   PENUMBRA_FILTER_SIZES[n]        filterSize
//   PENUMBRA_FILTER_FIRST_POISSON_DISK  the first filter of ShadowFilterFamily::PoissonDisk
//   PENUMBRA_BILINEAR_TAP_VARIANCE, PENUMBRA_NEAREST_TAP_VARIANCE  kBilinearTapVariance, kNearestTapVariance
//   PENUMBRA_GOLDEN_TURN            (cos, sin) of kGoldenAngle: the walk's turn from one tap to the next
//   penumbraSpiralMean(count)       spiralMean for each of kPoissonSampleCounts
std::string filterConstantsGlsl();

} // namespace penumbra::shadows
