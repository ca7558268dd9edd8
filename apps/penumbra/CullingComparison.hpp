#pragma once

#include "SceneBench.hpp"

#include <nlohmann/json.hpp>

namespace penumbra::apps {

// `penumbra bench --scene S --compare-culling`: the GPU-culled frame against the CPU path's (`culling gpu` and
// `cpu`), each configuration in one process: one device, a renderer for each culling, their frames alternated (GPU
// first in odd pairs, CPU first in even ones) so that the machine's drift over the run falls on both alike. Prints a
// table and returns {"cullingComparison": [{configuration, scene, width, height, frames (pairs measured), warmup,
// gpuFrameMs, cpuPathFrameMs (medians of wall time per frame), gpuOverCpu (their ratio), pairedGpuOverCpu (the median
// of each pair's ratio), gpuCpuFrameMs, cpuPathCpuFrameMs (planning + recording, medians)}]}. Throws rhi::Error as
// runSceneBench does.
nlohmann::json runCullingComparison(const SceneBenchOptions& options);

} // namespace penumbra::apps
