#pragma once

#include "DepthPrepass.hpp"
#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace penumbra::render {

// The contact shadow texture, at half the frame's resolution (texel q marched from pixel 2q): the marched pixel's
// view depth and its view depth step per pixel, exact, for the lit pass's nearest-depth upsampling, a bit per
// directional light 0 .. maxCollectedDirectionalLights - 1 and a bit per contact local light (contactLocalLights)
// that the march found occluded.
inline constexpr rhi::Format kContactShadowFormat = rhi::Format::RGBA32F;

// Texels per side of the contact shadow texture for `pixels` of the frame: one per two pixels, rounded up.
constexpr std::uint32_t contactShadowExtent(std::uint32_t pixels) { return (pixels + 1) / 2; }

// The contact pass's bindings: its block and the single-sampled view depth it marches through (kViewDepthFormat,
// written by the prepass).
inline constexpr std::uint32_t kContactBinding = 0;
inline constexpr std::uint32_t kContactDepthBinding = 1;

// The Contact block of shaders/contact_shadows.frag, std140.
struct ContactShadowUniforms {
    glm::mat4 worldToTexture{1.0f}; // rhi::Conventions::clipToTexture() times the view-projection
    glm::vec4 cameraPosition{0.0f};
    glm::vec4 cameraForward{0.0f};
    // The world-space ray through NDC (x, y) per metre of view depth is cameraForward + x * viewRayRight + y *
    // viewRayUp: the view's right and up over the projection's x and y scales, which no depth convention changes.
    glm::vec4 viewRayRight{0.0f};
    glm::vec4 viewRayUp{0.0f};
    // Unit, from the surface towards directional light i (LitFrameUniforms::lights[i].direction negated).
    std::array<glm::vec4, maxCollectedDirectionalLights> towardsLight{};
    // The spot and point lights of contactLocalLights, in its order: position and 1 / range^2; the spot cone's axis
    // (unit, away from the light) and the cosine of its outer angle, (0, 0, 0, -2) for a point light (every
    // direction).
    std::array<glm::vec4, shadows::kMaxContactLocalLights> localPosition{};
    std::array<glm::vec4, shadows::kMaxContactLocalLights> localCone{};
    glm::vec4 targetSize{0.0f}; // the frame's width, height in pixels
    std::int32_t lightCount = 0;
    std::int32_t steps = 0; // shadows::ContactShadowSettings
    float marchLength = 0.0f; // metres (GLSL reserves the name `length`)
    float thickness = 0.0f;
    std::int32_t localLightCount = 0;
    float nearPlane = 0.0f; // the camera's near plane's view depth
};

inline constexpr std::array kContactFields{
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, worldToTexture),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, cameraPosition),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, cameraForward),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, viewRayRight),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, viewRayUp),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, towardsLight),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, localPosition),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, localCone),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, targetSize),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, lightCount),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, steps),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, marchLength),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, thickness),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, localLightCount),
    PENUMBRA_SHADER_FIELD(ContactShadowUniforms, nearPlane),
};
// contact_shadows.frag's block Contact, read through the instance name `contact`.
inline constexpr shaders::ShaderStruct kContactBlock{"Contact", sizeof(ContactShadowUniforms), kContactFields};
static_assert(shaders::matchesLayout(kContactBlock, shaders::BlockLayout::Std140));

// The spot and point lights (their index in the lit pass's local order: spot lights, then point lights) that the
// contact march goes towards this frame, at most ContactShadowSettings::localLights: of those with a shadow map this
// frame (realtime or static) and a shadow strength, whose reach the camera's view may show, the nearest
// (shadows::nearestContactLights). A light's place in the list is its bit in the contact shadow texture
// (LocalLightRecord::contactBit).
std::vector<std::uint32_t> contactLocalLights(const scene::Scene& scene, const scene::Camera& camera,
                                              const FrameDesc& frame, const shadows::LocalShadowPlan& plan,
                                              const shadows::StaticShadowPlan& staticPlan);

// The Contact block of a frame from `camera`: the lit pass's frame block (its view-projection and directional
// lights), the scene's spot and point lights `localLights` (contactLocalLights) and the frame's size and settings.
ContactShadowUniforms contactShadowUniforms(const rhi::Conventions& conventions, const scene::Camera& camera,
                                            const FrameDesc& frame, const LitFrameUniforms& lit,
                                            const scene::Scene& scene, std::span<const std::uint32_t> localLights);

// The contact shadow march (shaders/contact_shadows.frag): one full-screen pass at half resolution over the
// single-sampled view depth that the prepass writes beside the lit depth (viewDepth(), shaders/view_depth.glsl) into
// shadows(), which the lit pass and the visibility view upsample at their pixel (shaders/contact_shadows_lit.glsl).
// Half resolution: a full-resolution pass costs a software rasterizer a tenth of the lit pass before it marches at all
// (docs/notes/2026-12-06-contact-shadows.md). View depth, not the depth buffer: the same in every depth convention
// (docs/notes/2026-12-07-contact-parity-cost.md).
class ContactShadowPass {
public:
    explicit ContactShadowPass(rhi::Device& device);

    // The targets (viewDepth() at the frame's size, shadows() at contactShadowExtent of each side) for frames of
    // `width` x `height`, and the single-sampled prepass that writes viewDepth() (with `receivers`: the screen-space
    // path's, DepthPrepass); call again whenever the frame's size or path changes.
    void prepare(std::uint32_t width, std::uint32_t height, bool receivers);
    const rhi::Texture& shadows() const { return *shadows_; }
    const rhi::Texture& viewDepth() const { return *viewDepth_; }
    // The single-sampled depth prepass that also writes viewDepth(): depth only, or with the receiver derivatives
    // (made by prepare).
    const DepthPrepass& prepass(bool receivers) const { return receivers ? *receiverPrepass_ : *prepass_; }
    // Nearest, clamped: what the lit pass reads shadows() with (texelFetch).
    const rhi::Sampler& sampler() const { return *sampler_; }

    void record(rhi::CommandList& commands, const rhi::UniformSlice& uniforms);

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Texture> shadows_, viewDepth_;
    std::unique_ptr<rhi::Framebuffer> target_;
    std::unique_ptr<DepthPrepass> prepass_, receiverPrepass_;
};

// The frame pass of ContactShadowPass: after the prepasses, before the lit pass.
class ContactShadowsPass final : public FramePass {
public:
    ContactShadowsPass(const FrameState& state, ContactShadowPass* pass) : state_(state), pass_(pass) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    ContactShadowPass* pass_; // null until a frame asks for contact shadows
};

} // namespace penumbra::render
