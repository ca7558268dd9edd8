#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

namespace penumbra::shadows {

// The per-draw block ShadowCasterDraw of the caster shaders (generated into caster_block.glsl); the casters' model
// matrices are per instance (InstanceTransform).
struct ShadowCasterUniforms {
    glm::mat4 viewProjection{1.0f}; // the view's light view-projection
    float alpha = 1.0f;
    float alphaCutoff = 0.0f;
    std::int32_t casterMode = 0; // ShadowCasterMode
    std::int32_t pancake = 0; // 1: clamp to the near plane in the shader (no depth clamp)
    // Added to gl_FragCoord, so the dither follows the world-fixed texel grid.
    glm::vec2 ditherOrigin{0.0f};
    std::int32_t textured = 0; // 1: the alpha comes from the base colour texture
    alignas(16) UvTransformRows baseColorUv{}; // ShadowCaster::baseColorUv
    // The caster-side normal offset (CasterNormalOffset), read where reach > 0: the direction into the scene (w = 0)
    // or the light's position (w = 1), and the lookup reach in world units (per unit of distance from a positional
    // light).
    glm::vec4 light{0.0f};
    float reach = 0.0f;
};

inline constexpr std::array kShadowCasterFields{
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, viewProjection),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, alpha),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, alphaCutoff),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, casterMode),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, pancake),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, ditherOrigin),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, textured),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, baseColorUv),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, light),
    PENUMBRA_SHADER_FIELD(ShadowCasterUniforms, reach),
};
// The block ShadowCasterDraw, read through the instance name `draw`.
inline constexpr shaders::ShaderStruct kShadowCasterBlock{"ShadowCasterDraw", sizeof(ShadowCasterUniforms),
                                                          kShadowCasterFields};
static_assert(shaders::matchesLayout(kShadowCasterBlock, shaders::BlockLayout::Std140));

// One shadow view's casters, drawn into the bound target's current viewport.
struct ShadowViewDraw {
    glm::mat4 viewProjection{1.0f};
    float slopeScaleBias = 0.0f;
    float depthBias = 0.0f; // the rasteriser's constant depth bias, in the depth format's steps
    // Orthographic views pancake casters in front of the near plane onto it; perspective views must
    // not (clamping would distort casters behind the light).
    bool pancake = false;
    // Cube-map faces are mirrored views (rhi::cubeFaceView): their front faces are clockwise in NDC.
    bool mirrored = false;
    glm::vec2 ditherOrigin{0.0f}; // added to gl_FragCoord: the dither's grid origin
    CasterNormalOffset normalOffset; // the caster-side normal bias; none by default
};

// One atlas tile's view and the casters drawn into it.
struct ShadowTileDraw {
    std::uint32_t tile = 0;
    rhi::Viewport viewport;
    ShadowViewDraw view;
    std::vector<std::uint32_t> casters; // indices into the caster list
    CasterVolume volume; // what the casters were culled against, for the GPU culling pass
};

// Tiles whose casters a GpuCasterCulling culled: tile i of a pass's tileDraws is the culling's tile firstTile + i.
struct CulledTiles {
    const GpuCasterCulling& culling;
    std::uint32_t firstTile = 0;
};

// The shadow caster shaders and pipelines every shadow pass shares, and its per-draw uniforms.
class ShadowCasterDraws {
public:
    // Builds the caster pipelines for vertices of `vertexFormat`.
    ShadowCasterDraws(rhi::Device& device, const CasterVertexFormat& vertexFormat);

    // Forget the previous record's uniforms and instances; call once per command list, before the first draw.
    void reset()
    {
        uniforms_.reset();
        instances_.reset();
    }

    // Draws casters[indices] with the view, the casters of each draw group (ShadowCaster::drawGroup) as the
    // instances of one draw; returns the draws issued. Throws rhi::Error for an index past the caster list and for a
    // draw group whose casters do not draw alike.
    std::uint32_t draw(rhi::CommandList& commands, rhi::Format depthFormat, const ShadowViewDraw& view,
                       std::span<const std::uint32_t> indices, std::span<const ShadowCaster> casters);

    // Draws the casters `culling` culled into `tile` (its last record, from this list's casters) with the view: an
    // indirect draw with a count per batch, whose instances the culling pass wrote; returns the draws recorded.
    std::uint32_t drawCulled(rhi::CommandList& commands, rhi::Format depthFormat, const ShadowViewDraw& view,
                             const GpuCasterCulling& culling, std::uint32_t tile,
                             std::span<const ShadowCaster> casters);

private:
    // Indexed by ShadowCaster::doubleSided: culled, not culled.
    struct Pipelines {
        std::array<std::unique_ptr<rhi::Pipeline>, 2> opaque;
        std::array<std::unique_ptr<rhi::Pipeline>, 2> alphaTested;
    };
    const Pipelines& pipelines(rhi::Format depthFormat, bool clamp, bool mirrored);
    // Binds the batch's pipeline (where it differs from `bound`), its uniforms, texture, vertices and indices.
    void bindBatch(rhi::CommandList& commands, const Pipelines& pipelines, const ShadowViewDraw& view,
                   const ShadowCaster& caster, std::uint32_t index, const rhi::Pipeline*& bound);

    rhi::Device& device_;
    CasterVertexFormat vertexFormat_;
    std::unique_ptr<rhi::Shader> vertex_;
    std::unique_ptr<rhi::Shader> opaqueFragment_;
    std::unique_ptr<rhi::Shader> alphaFragment_;
    std::map<std::tuple<rhi::Format, bool, bool>, Pipelines> pipelines_;
    rhi::UniformArena uniforms_;
    rhi::VertexArena instances_;
};

// Scissor rectangle of a whole-texel viewport.
rhi::Rect scissorOf(const rhi::Viewport& viewport);

} // namespace penumbra::shadows
