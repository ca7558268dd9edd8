#pragma once

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::render {

struct FrameDesc {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    shadows::ShadowSettings shadows;
    glm::vec3 ambient{0.03f};
    bool cascadeView = false; // also render the lit image tinted by cascade index
};

struct FrameStats {
    std::uint32_t casterDraws = 0;                  // issued into the atlas
    std::uint32_t casterDrawsWithoutCullingBias = 0; // casters overlapping each cascade's light box
    std::optional<double> atlasPassMs;              // GPU time, where the device has timestamps
    std::optional<double> litPassMs;
};

// Draws a scene with cascaded directional shadows: plan (CPU) -> caster pass into the atlas ->
// lit pass (and optionally the cascade view). One submission per frame; the results stay readable
// until the next render().
class SceneRenderer {
public:
    // The scene must outlive the renderer; it is validated and its meshes uploaded here.
    SceneRenderer(rhi::Device& device, const scene::Scene& scene);

    // Throws rhi::Error for settings out of range (naming the field) or a zero-sized frame.
    FrameStats render(const scene::Camera& camera, const FrameDesc& frame);

    const rhi::Texture& litImage() const { return *lit_; }
    const rhi::Texture& cascadeImage() const { return *cascades_; }
    const shadows::ShadowAtlas& atlas() const { return *atlas_; }
    const shadows::DirectionalShadowPlan& plan() const { return plan_; }
    // Why lights are drawn without shadows, or not at all (beyond maxLitDirectionalLights).
    const std::vector<std::string>& notes() const { return notes_; }

private:
    void prepareTargets(const FrameDesc& frame);
    LitFrameUniforms frameUniforms(const scene::Camera& camera, const FrameDesc& frame, LitView view) const;
    void recordLitPass(rhi::CommandList& commands, const rhi::Framebuffer& target, const LitFrameUniforms& frame,
                       const rhi::UniformSlice& shadowUniforms);

    rhi::Device& device_;
    GpuScene gpuScene_;
    shadows::DirectionalShadowPass shadowPass_;
    std::unique_ptr<rhi::Shader> litVertex_;
    std::unique_ptr<rhi::Shader> litFragment_;
    std::unique_ptr<rhi::Pipeline> litPipeline_;
    std::unique_ptr<rhi::CommandList> commands_;
    std::unique_ptr<rhi::TimestampQueries> timestamps_;
    rhi::UniformArena uniforms_;

    std::unique_ptr<shadows::ShadowAtlas> atlas_;
    std::unique_ptr<rhi::Texture> lit_;
    std::unique_ptr<rhi::Texture> cascades_;
    std::unique_ptr<rhi::Texture> depth_;
    std::unique_ptr<rhi::Framebuffer> litTarget_;
    std::unique_ptr<rhi::Framebuffer> cascadeTarget_;

    shadows::DirectionalShadowPlan plan_;
    std::vector<std::string> notes_;
};

} // namespace penumbra::render
