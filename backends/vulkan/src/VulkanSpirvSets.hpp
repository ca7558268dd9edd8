#pragma once

#include "VulkanLayouts.hpp"

#include "penumbra/rhi/Shader.hpp"

#include <cstdint>
#include <vector>

namespace penumbra::vulkan {

// The shader's SPIR-V with each resource moved to the descriptor set `layout` places its binding number in.
// Shaders declare one flat namespace of binding numbers (rhi/Shader.hpp), which glslang puts in set 0; the set a
// binding goes to is the pipeline's to decide, so the shaders say nothing of it on any backend.
std::vector<std::uint32_t> assignDescriptorSets(const rhi::CompiledShader& shader, const DescriptorLayout& layout);

} // namespace penumbra::vulkan
