#pragma once

#include "penumbra/scene/Light.hpp"
#include "penumbra/truth/TruthComparison.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::apps {

// One shadowed light of `penumbra truth`: the ray cast, the renderer's visibility view and their comparison.
struct LightTruth {
    scene::LightRef light;
    std::string name;
    truth::LightVisibilityMask raycast;
    truth::RenderedVisibility rendered;
    truth::TruthComparison comparison;
    float contactGapTexels = 0.0f;
    truth::ContactGapFigures contactGaps; // casters within contact.length, whether the frame marches or not
};

// DIR/raycast.png (ray-cast visibility), DIR/shadowmap.png (the shadow maps' visibility) and
// DIR/disagreement.png (acne red, leaks blue, both magenta; edges left out dark amber; agreement light grey where
// lit, darker where shadowed). Grey levels average the lights; with several lights, each light's three pictures
// are also written as NAME-<n>.png, n its position in truth.json's `lights` from 1.
void writeTruthPictures(const std::filesystem::path& folder, const std::vector<LightTruth>& lights);

} // namespace penumbra::apps
