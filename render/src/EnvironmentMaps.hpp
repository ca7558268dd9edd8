#pragma once

#include "penumbra/render/Environment.hpp"
#include "penumbra/rhi/Device.hpp"

#include <memory>
#include <optional>

namespace penumbra::render {

// The lit pass's environment textures: the specular chain prefiltered on the GPU (shaders/environment_prefilter.comp)
// and the split-sum BRDF table, with black stand-ins while the frame has no environment. Prefiltering runs once per
// environment image, in a submission of its own before the frame's (like GpuScene's uploads), not as a FramePass:
// frames that keep the environment do no work for it.
class EnvironmentMaps {
public:
    explicit EnvironmentMaps(rhi::Device& device);
    ~EnvironmentMaps();

    // Makes `image` the bound environment (nullptr: none), prefiltering it unless it is the one prefiltered last.
    // Returns the milliseconds prefiltering took (resampling, SH9 projection, upload, dispatches, waiting for them),
    // nullopt where nothing was prefiltered.
    std::optional<double> use(const std::shared_ptr<const EnvironmentImage>& image);
    // The specular chain (or its stand-in) and the BRDF table at kLitEnvironmentSpecularBinding and
    // kLitEnvironmentBrdfBinding.
    void bind(rhi::CommandList& commands) const;

    bool present() const { return image_ != nullptr; }
    // The lit shader's diffuse coefficients at intensity 1 (diffuseShaderCoefficients of the resampled image).
    const Sh9& diffuse() const { return diffuse_; }
    // The prefiltered chain: RGBA16F, kEnvironmentWidth x kEnvironmentHeight, kEnvironmentLevels levels. Throws
    // rhi::Error while no environment is in use.
    const rhi::Texture& specular() const;
    // The resampled source as uploaded (RGBA16F, the chain's size and levels, box-filtered mips).
    const rhi::Texture& source() const;

private:
    void prefilter(const EnvironmentImage& image);

    rhi::Device& device_;
    std::shared_ptr<const EnvironmentImage> image_;
    Sh9 diffuse_{};
    std::unique_ptr<rhi::Texture> blank_; // 1 x 1 black: the chain and table without an environment
    std::unique_ptr<rhi::Sampler> wrapSampler_; // around in u, clamped at the poles, trilinear
    std::unique_ptr<rhi::Sampler> clampSampler_;
    std::unique_ptr<rhi::ComputePipeline> pipeline_; // created with the first environment
    std::unique_ptr<rhi::Texture> brdf_;
    std::unique_ptr<rhi::Texture> source_;
    std::unique_ptr<rhi::Texture> specular_;
};

} // namespace penumbra::render
