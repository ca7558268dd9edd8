#include "DispatchScene.hpp"

namespace penumbra::apps {
namespace {

const char* const countersGlsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Counters { uint counts[64]; };
void main()
{
    counts[gl_LocalInvocationIndex] += 1u;
}
)";

} // namespace

DispatchScene::DispatchScene(rhi::Device& device, std::uint32_t count) : count_(count)
{
    const std::unique_ptr<rhi::Shader> shader =
        device.createShader({rhi::ShaderStage::Compute, countersGlsl, "bench_counters.comp"});
    pipeline_ = device.createComputePipeline(
        {.compute = shader.get(),
         .storageLayouts = {{"Counters", sizeof(Counters), {{"counts", 0, sizeof(Counters)}}}},
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
