#pragma once

#include "penumbra/scene/LightShadowOptions.hpp"

// The light vocabulary of the scene (scene/LightShadowOptions.hpp) is the shadows' own: one type per concept, so
// the renderer hands scene lights to the planners without translating.
namespace penumbra::shadows {

using scene::kShadowFilterCount;
using scene::LightKind;
using scene::LightShadowDefaults;
using scene::NormalBiasSide;
using scene::ShadowFilter;
using scene::StaticShadowUpdate;

} // namespace penumbra::shadows
