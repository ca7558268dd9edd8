#include "DepthReduction.hpp"

#include "penumbra/rhi/UniformLayout.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>

namespace penumbra::render {
namespace {

// The storage block of depth_reduction.comp.
struct DepthBounds {
    std::uint32_t nearest;
    std::uint32_t farthest;
};

// What the buffer holds before the dispatch: nothing drawn.
constexpr DepthBounds kEmpty{0xffffffffu, 0u};
constexpr std::uint32_t kGroupSize = 16; // the shader's local_size_x and _y

float windowDepthOf(std::uint32_t bits)
{
    float depth = 0.0f;
    std::memcpy(&depth, &bits, sizeof depth);
    return depth;
}

} // namespace

DepthReduction::DepthReduction(rhi::Device& device)
{
    const auto clear = static_cast<std::int64_t>(device.conventions().clearDepth());
    const std::unique_ptr<rhi::Shader> shader =
        device.createShader(shaders::load("depth_reduction.comp", {{"CLEAR_DEPTH", clear}}));
    pipeline_ = device.createComputePipeline({.compute = shader.get(),
                                              .storageLayouts = {{"DepthBounds",
                                                                  sizeof(DepthBounds),
                                                                  {PENUMBRA_UNIFORM_MEMBER(DepthBounds, nearest),
                                                                   PENUMBRA_UNIFORM_MEMBER(DepthBounds, farthest)}}},
                                              .debugName = "depth reduction"});
    sampler_ = device.createSampler(
        {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "depth reduction"});
    bounds_ = device.createBuffer(
        {.size = sizeof(DepthBounds), .usage = rhi::BufferUsage::Storage, .debugName = "depth reduction bounds"});
}

void DepthReduction::record(rhi::CommandList& commands, const rhi::Texture& depth)
{
    bounds_->writeObject(kEmpty);
    commands.bindComputePipeline(*pipeline_);
    commands.bindTexture(0, depth, *sampler_);
    commands.bindStorageBuffer(1, *bounds_, 0, sizeof(DepthBounds));
    const rhi::TextureDesc& size = depth.desc();
    commands.dispatch((size.width + kGroupSize - 1) / kGroupSize, (size.height + kGroupSize - 1) / kGroupSize);
    recorded_ = true;
}

std::optional<shadows::ViewDepthRange> DepthReduction::read(const rhi::Conventions& conventions,
                                                            const glm::mat4& projection)
{
    if (!recorded_)
        return std::nullopt;
    recorded_ = false;
    DepthBounds bounds{};
    bounds_->read(0, std::as_writable_bytes(std::span(&bounds, 1)));
    if (bounds.nearest > bounds.farthest)
        return std::nullopt;
    // Reversed Z stores the nearest surface at the larger depth: order the two by view depth.
    const float a = conventions.viewDepth(projection, windowDepthOf(bounds.nearest));
    const float b = conventions.viewDepth(projection, windowDepthOf(bounds.farthest));
    return shadows::ViewDepthRange{std::min(a, b), std::max(a, b)};
}

} // namespace penumbra::render
