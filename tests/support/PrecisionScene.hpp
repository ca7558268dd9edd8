#pragma once

#include "penumbra/rhi/Device.hpp"

namespace penumbra::testing {

struct ZFighting {
    int fighting = 0; // pixels where the farther quad shows through the nearer one
    int pixels = 0;
};

// Draws the farther of two nearly coplanar quads first, then the nearer with a strict
// Nearer test, and counts the pixels where the nearer one did not win.
ZFighting countZFighting(rhi::Device& device);

} // namespace penumbra::testing
