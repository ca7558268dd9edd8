#include "VulkanDrawCount.hpp"

#include "VulkanPipeline.hpp"
#include "VulkanResources.hpp"

#include <array>

namespace penumbra::vulkan {
namespace {

// One invocation per command. The patched buffer starts with the four parameters the host wrote, then the commands.
const char* const patchGlsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Arguments { uint words[]; } arguments;
layout(std430, binding = 1) readonly buffer Count { uint words[]; } count;
layout(std430, binding = 2) buffer Patched {
    uint argumentWord;
    uint countWord;
    uint maxDrawCount;
    uint commandWords;
    uint words[];
} patched;
void main()
{
    uint draw = gl_GlobalInvocationID.x;
    if (draw >= patched.maxDrawCount)
        return;
    uint drawn = min(count.words[patched.countWord], patched.maxDrawCount);
    uint first = draw * patched.commandWords;
    for (uint w = 0u; w < patched.commandWords; ++w)
        patched.words[first + w] = arguments.words[patched.argumentWord + first + w];
    if (draw >= drawn)
        patched.words[first + 1u] = 0u; // instanceCount, the second word of both commands
}
)";

constexpr std::uint32_t workgroupSize = 64;

void memoryBarrier(VkCommandBuffer commands, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStages, VkAccessFlags dstAccess)
{
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(commands, srcStages, dstStages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace

DrawCountEmulation::DrawCountEmulation(std::shared_ptr<Context> context)
    : context_(std::move(context)), descriptors_(context_)
{
}

DrawCountEmulation::~DrawCountEmulation() = default;

VkBuffer DrawCountEmulation::patch(VkCommandBuffer commands, const VulkanBuffer& arguments, VkDeviceSize offset,
                                   const VulkanBuffer& count, VkDeviceSize countOffset, std::uint32_t maxDrawCount,
                                   std::uint32_t commandWords)
{
    if (!pipeline_) {
        shader_ = std::make_unique<VulkanShader>(context_, rhi::compileShader({rhi::ShaderStage::Compute, patchGlsl,
                                                                               "draw-count-emulation.comp"},
                                                                              context_->conventions.glslHeader()));
        pipeline_ = std::make_unique<VulkanComputePipeline>(
            context_, rhi::ComputePipelineDesc{.compute = shader_.get(), .debugName = "draw count emulation"});
    }
    const std::uint64_t commandBytes = std::uint64_t(maxDrawCount) * commandWords * sizeof(std::uint32_t);
    auto& patched = *patched_.emplace_back(
        std::make_unique<VulkanBuffer>(context_, rhi::BufferDesc{.size = commandsOffset + commandBytes,
                                                                 .usage = rhi::BufferUsage::Indirect,
                                                                 .debugName = "draw count emulation"}));
    const std::array<std::uint32_t, 4> parameters{std::uint32_t(offset / 4), std::uint32_t(countOffset / 4),
                                                  maxDrawCount, commandWords};
    patched.writeObject(parameters);

    // The arguments and the count may come from a dispatch or a copy before the pass.
    memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_->handle());
    descriptors_.setPipeline(pipeline_->descriptors());
    descriptors_.set(0, {.kind = rhi::BindingKind::StorageBuffer,
                         .buffer = arguments.handle(),
                         .size = arguments.desc().size});
    descriptors_.set(1, {.kind = rhi::BindingKind::StorageBuffer, .buffer = count.handle(), .size = count.desc().size});
    descriptors_.set(2, {.kind = rhi::BindingKind::StorageBuffer,
                         .buffer = patched.handle(),
                         .size = patched.desc().size});
    descriptors_.rebind();
    descriptors_.flush(commands);
    vkCmdDispatch(commands, (maxDrawCount + workgroupSize - 1) / workgroupSize, 1, 1);
    memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
    return patched.handle();
}

void DrawCountEmulation::reset()
{
    descriptors_.reset();
    patched_.clear();
}

} // namespace penumbra::vulkan
