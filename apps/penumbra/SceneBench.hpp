#pragma once

#include "SceneOptions.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// `penumbra bench --scene S`: any built-in or glTF scene, N frames in one process per configuration after K
// warm-up frames, each pass's GPU time (timestamps) and each frame's wall time (planning, recording, submission
// and the wait for the GPU), medians and spread.
struct SceneBenchOptions {
    SceneOptions scene;
    std::vector<std::string> backends = {"vulkan", "opengl"};
    std::uint32_t frames = 20;
    std::uint32_t warmup = 3;
    bool validate = false;
    // --lights N,M,...: the run repeated for each count of the scene's first local lights (SceneOptions::localLights).
    std::vector<std::uint32_t> lightCounts;
};

// The pass names of the JSON's "passes" objects, in frame order: the depth prepasses (with the single-sampled one
// that depth fit and contact shadows read under MSAA), the directional and the local atlas, the screen-space shadows,
// the lit pass, the resolve, and the minimal reference lit pass (timed in a frame of its own, which the frame times
// leave out); then the static shadow maps drawn in the frame (drawn first, listed last to keep the older names'
// order), the contact shadows' march, the depth fit's reduction, the GPU caster culling pass (--culling gpu), the
// light cluster build and the GPU view culling pass (--culling gpu with instancing).
inline constexpr const char* kBenchPassNames[] = {
    "depth",       "directionalAtlas", "otherAtlas", "screenSpaceShadows", "lit",           "resolve",    "reference",
    "staticAtlas", "contactShadows",   "depthFit",   "casterCulling",      "lightClusters", "viewCulling"};

// Prints a table per light count and returns {"scene": [one object per light count and configuration: configuration,
// scene, lights (the --lights count or null), width, height,
// frames, warmup, culling ("cpu" or "gpu"), clusterBuild ("cpu" or "gpu"), frameMs (median), frameMsMin, frameMsMax,
// passes {name: median ms}, passesMin, passesMax, litOverReference, instancing, cpuMs {planning, recording} (medians),
// cpuMsMax, draws {depth, lit}, casterDraws, cpuFrameMs (planning + recording, median), shadowedLights,
// lightsWithoutShadow, localTilesDrawn and localTilesCached (medians), movingCars (--moving-cars), localLightsRedrawn
// (median) and localLightsRedrawnMax, and redrawReasons {reason: light redraws over the measured frames}]}. A pass the
// frame does not draw reports 0. Throws rhi::Error for a device that is missing or, with validate, reports a message.
nlohmann::json runSceneBench(const SceneBenchOptions& options);

// "bench vulkan: frame 12/20", redrawn on one line of stderr.
void showBenchProgress(const std::string& configuration, std::uint32_t done, std::uint32_t total);

} // namespace penumbra::apps
