#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <glm/mat4x4.hpp>
#include <span>
#include <vector>

namespace penumbra::render {

// A tile rendered with a perspective projection (spot lights, point light faces).
struct PerspectiveTile {
    rhi::Viewport viewport;
    glm::mat4 projection{1.0f};
};

// The tiles of the local atlas, for the two functions below.
std::vector<PerspectiveTile> perspectiveTiles(const shadows::LocalShadowPlan& plan);
// The tiles of the static local atlas: the spot and point lights' static maps.
std::vector<PerspectiveTile> perspectiveTiles(const shadows::StaticShadowPlan& plan);

// Per texel, where its light depth lies between the light's far (0) and near (1) planes, linear in
// view depth: orthographic shadow projections store depth linearly in every convention; texels of
// `perspectiveTiles` are turned back into view depth with their projection. Atlases of different
// conventions are compared in it.
std::vector<float> lightDepthFraction(const rhi::DepthImage& atlas, const rhi::Conventions& conventions,
                                      std::span<const PerspectiveTile> perspectiveTiles = {});

// The atlas as a greyscale RGBA8 picture of lightDepthFraction, the same in every convention: white at
// the light's near plane, black at the far plane (the cleared background), row 0 at the top.
rhi::Image atlasPicture(const rhi::DepthImage& atlas, const rhi::Conventions& conventions,
                        std::span<const PerspectiveTile> perspectiveTiles = {});

} // namespace penumbra::render
