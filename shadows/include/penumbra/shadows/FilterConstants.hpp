#pragma once

#include <string>

namespace penumbra::shadows {

// The GLSL include "shadow_constants.glsl" of the lit shader: the ShadowFilter values, their kernel sizes and the
// Poisson disks of 16, 32 and 64 points, so that every number is written once, in C++.
//   PENUMBRA_FILTER_<NAME>          ShadowFilter values (PCF2X2 .. PCSS)
//   PENUMBRA_FILTER_SIZES[n]        filterSize
//   PENUMBRA_POISSON_DISK[112]      the disks of poissonDisk(16), (32), (64) one after the other: disk n starts at
//                                   n - 16
std::string filterConstantsGlsl();

} // namespace penumbra::shadows
