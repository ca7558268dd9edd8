#pragma once

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/GpuLightClusters.hpp"
#include "penumbra/shadows/LightClusters.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstddef>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::render {

// Every spot and point light of the scene in the lit pass's order (spot lights, then point lights): where it is, its
// colour, cone and shadows, and its bit among `contactLights` (the frame's contact local lights, contactLocalLights).
std::vector<LocalLightRecord> localLightRecords(const scene::Scene& scene, const shadows::LocalShadowPlan& plan,
                                                const shadows::StaticShadowPlan& staticPlan,
                                                std::span<const std::uint32_t> contactLights);

// The reach of every spot and point light, in the same order, as shadows::buildLightClusters takes it.
std::vector<shadows::ClusterLight> clusterLights(const scene::Scene& scene);

// The cluster fields of the lit pass's Frame block: the camera's view frame and the slices of `grid`.
void setClusterView(LitFrameUniforms& u, const shadows::ShadowCamera& camera,
                    const shadows::LightClusterUniforms& grid);

// The lit pass's local light, cluster and light index textures (LitUniforms.hpp's layout), uploaded when their
// contents change (a still camera and still lights upload nothing) and grown by powers of two of rows as the frame
// needs. With LightClusterBuild::Gpu the light cluster pass writes the cluster and index textures instead.
class LocalLightTextures {
public:
    explicit LocalLightTextures(rhi::Device& device);

    void updateLights(std::span<const LocalLightRecord> lights);
    // This frame's lists of `lights` seen by `camera`: built and uploaded here (Cpu), or their inputs kept and the
    // textures made ready for recordGpuLists (Gpu). Returns their grid.
    shadows::LightClusterUniforms prepareLists(const shadows::ShadowCamera& camera,
                                               std::span<const shadows::ClusterLight> lights,
                                               shadows::LightClusterBuild build);
    // Whether this frame's lists are to be built by recordGpuLists.
    bool gpuLists() const { return gpuInputs_.has_value(); }
    // Records the GPU build of the lists prepareLists kept into `ranges` and `indices`: clusters() and indices().
    void recordGpuLists(rhi::CommandList& commands, const rhi::Texture& ranges, const rhi::Texture& indices);

    const rhi::Texture& lights() const { return *lights_.texture; }
    const rhi::Texture& clusters() const { return *clusters_.texture; }
    const rhi::Texture& indices() const { return *indices_.texture; }
    // At kLitLocalLightsBinding, kLitLightClustersBinding and kLitLightIndicesBinding.
    void bind(rhi::CommandList& commands) const;

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Sampler> sampler_; // nearest: texelFetch ignores it, the binding needs one
    // A data texture and the bytes last uploaded into it.
    struct DataTexture {
        std::unique_ptr<rhi::Texture> texture;
        std::vector<std::byte> uploaded;
    };
    void reserve(DataTexture& target, rhi::Format format, const char* name, std::uint32_t rows,
                 rhi::TextureUsage usage);
    void upload(DataTexture& target, rhi::Format format, const char* name, std::span<const std::byte> data);
    DataTexture lights_;
    DataTexture clusters_;
    DataTexture indices_;
    std::unique_ptr<shadows::GpuLightClusters> gpuBuild_; // made at the first frame that builds on the GPU
    std::optional<shadows::LightClusterInputs> gpuInputs_;
};

} // namespace penumbra::render
