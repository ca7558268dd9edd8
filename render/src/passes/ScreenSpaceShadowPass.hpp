#pragma once

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

namespace penumbra::render {

// The screen-space shadow texture: one channel per collected directional light, full float, so the lit pass reads
// the attenuation the forward path would compute.
inline constexpr rhi::Format kScreenSpaceShadowFormat = rhi::Format::RGBA32F;

// The collection's own bindings, after the lit pass's (its shadow maps keep the lit pass's numbers).
inline constexpr std::uint32_t kCollectionBinding = kLitScreenSpaceDepthBinding + 1;
inline constexpr std::uint32_t kCollectionDepthBinding = kLitScreenSpaceDepthBinding + 2;
inline constexpr std::uint32_t kCollectionPositionDxBinding = kLitScreenSpaceDepthBinding + 3;
inline constexpr std::uint32_t kCollectionPositionDyBinding = kLitScreenSpaceDepthBinding + 4;

// The Collection block of shaders/screen_space_shadows.frag, std140.
struct ScreenSpaceShadowUniforms {
    glm::mat4 clipToWorld{1.0f};
    glm::vec4 cameraPosition{0.0f};
    glm::vec4 cameraForward{0.0f};
    std::int32_t lightCount = 0; // lights collected
    alignas(16) std::array<LitDirectionalLight, maxCollectedDirectionalLights> lights{}; // LitFrameUniforms::lights
    glm::vec4 targetSize{0.0f}; // width, height in pixels
};

inline constexpr std::array kCollectionFields{
    PENUMBRA_SHADER_FIELD(ScreenSpaceShadowUniforms, clipToWorld),
    PENUMBRA_SHADER_FIELD(ScreenSpaceShadowUniforms, cameraPosition),
    PENUMBRA_SHADER_FIELD(ScreenSpaceShadowUniforms, cameraForward),
    PENUMBRA_SHADER_FIELD(ScreenSpaceShadowUniforms, lightCount),
    PENUMBRA_SHADER_STRUCT_FIELD(ScreenSpaceShadowUniforms, lights, kLitDirectionalLightStruct),
    PENUMBRA_SHADER_FIELD(ScreenSpaceShadowUniforms, targetSize),
};
// screen_space_shadows.frag's block Collection, read through the instance name `collection`.
inline constexpr shaders::ShaderStruct kCollectionBlock{"Collection", sizeof(ScreenSpaceShadowUniforms),
                                                        kCollectionFields};
static_assert(shaders::matchesLayout(kCollectionBlock, shaders::BlockLayout::Std140));

// The lit pass's frame block as the collection reads it: the inverse of its view-projection (inverted in double, so
// the reconstructed positions lose no more than the depth's own precision), its camera and its first lights.
ScreenSpaceShadowUniforms screenSpaceShadowUniforms(const LitFrameUniforms& frame, std::uint32_t width,
                                                    std::uint32_t height);

// The screen-space shadow collection (shaders/screen_space_shadows.frag): after the depth prepass with receivers
// (DepthPrepass), one full-screen pass into shadows(). It owns the prepass's derivative targets and the shadow
// texture, made for the depth texture prepare() is given.
class ScreenSpaceShadowPass {
public:
    // `shadowMaps`: the layout of the lit pass's shadow map set (ShadowMapBindings), which the pipelines list.
    ScreenSpaceShadowPass(rhi::Device& device, const rhi::BindingSetLayout& shadowMaps);

    // The targets for `depth` (single-sampled, sampled); call again whenever the depth texture is made anew.
    void prepare(const rhi::Texture& depth);
    // The receiver prepass's framebuffer: the two derivative targets and prepare()'s depth.
    const rhi::Framebuffer& receiverTarget() const { return *receiverTarget_; }
    const rhi::Texture& shadows() const { return *shadows_; }
    // The receiver prepass's world position derivatives (receiverTarget()'s colours).
    const rhi::Texture& positionDx() const { return *positionDx_; }
    const rhi::Texture& positionDy() const { return *positionDy_; }
    const rhi::Texture& depth() const { return *depth_; }
    // Nearest, clamped: what the lit pass reads shadows() and depth() with (texelFetch).
    const rhi::Sampler& sampler() const { return *sampler_; }

    // Opens the pass into shadows() with the pipeline for `features` (its shadow parts: static maps, filters)
    // and the collection's own inputs bound; the caller then binds the lit pass's shadow maps and calls draw().
    void begin(rhi::CommandList& commands, const LitShaderFeatures& features, const rhi::UniformSlice& uniforms);
    // The full-screen triangle; closes the pass.
    void draw(rhi::CommandList& commands) const;

private:
    const rhi::Pipeline& pipeline(const LitShaderFeatures& features);

    rhi::Device& device_;
    const rhi::BindingSetLayout& shadowMaps_;
    std::unique_ptr<rhi::Shader> vertex_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unordered_map<std::uint32_t, std::unique_ptr<rhi::Shader>> fragments_; // by shadowFeatureKey
    std::unordered_map<std::uint32_t, std::unique_ptr<rhi::Pipeline>> pipelines_; // by shadowFeatureKey
    const rhi::Texture* depth_ = nullptr;
    std::unique_ptr<rhi::Texture> positionDx_, positionDy_, shadows_;
    std::unique_ptr<rhi::Framebuffer> receiverTarget_, shadowTarget_;
};

} // namespace penumbra::render
