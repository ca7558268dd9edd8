#include "DispatchScene.hpp"

#include "penumbra/shaders/ShaderBlock.hpp"

namespace penumbra::apps {
namespace {

constexpr std::array kDispatchCountersFields{PENUMBRA_SHADER_FIELD(DispatchScene::Counters, counts)};
constexpr shaders::ShaderStruct kDispatchCountersBlock{"Counters", sizeof(DispatchScene::Counters),
                                                       kDispatchCountersFields};
static_assert(shaders::matchesLayout(kDispatchCountersBlock, shaders::BlockLayout::Std430));

const char* const countersGlsl = R"(#version 450
layout(local_size_x = 64) in;
#include "counters_block.glsl"
void main()
{
    counts[gl_LocalInvocationIndex] += 1u;
}
)";

} // namespace

DispatchScene::DispatchScene(rhi::Device& device, std::uint32_t count) : count_(count)
{
    const std::unique_ptr<rhi::Shader> shader = device.createShader(
        {rhi::ShaderStage::Compute,
         countersGlsl,
         "bench_counters.comp",
         {{"counters_block.glsl",
           shaders::storageBlockGlsl(kDispatchCountersBlock, countersBinding, "", shaders::BlockAccess::ReadWrite)}}});
    pipeline_ = device.createComputePipeline({.compute = shader.get(),
                                              .storageLayouts = {shaders::storageLayout(kDispatchCountersBlock)},
                                              .debugName = "bench counters"});
    counters_ = device.createBuffer(
        {.size = sizeof(Counters), .usage = rhi::BufferUsage::Storage, .debugName = "bench counters"});
    counters_->writeObject(Counters{});
}

void DispatchScene::recordRhi(rhi::CommandList& commands) const
{
    commands.bindComputePipeline(*pipeline_);
    commands.bindStorageBuffer(countersBinding, *counters_, 0, sizeof(Counters));
    for (std::uint32_t i = 0; i < count_; ++i)
        commands.dispatch(1);
}

} // namespace penumbra::apps
