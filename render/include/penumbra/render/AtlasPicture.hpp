#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"

#include <vector>

namespace penumbra::render {

// A shadow atlas as a greyscale RGBA8 picture, the same in every convention: white at the light's
// near plane, black at the far plane (the cleared background), rows as read back (row 0 at the top).
// Per texel, where its depth lies between the light's far (0) and near (1) planes. Orthographic
// shadow projections map light depth linearly in every convention, so this is linear light depth
// relative to the tile's planes: atlases of different conventions are compared in it.
std::vector<float> lightDepthFraction(const rhi::DepthImage& atlas, const rhi::Conventions& conventions);

rhi::Image atlasPicture(const rhi::DepthImage& atlas, const rhi::Conventions& conventions);

} // namespace penumbra::render
