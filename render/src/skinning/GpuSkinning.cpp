#include "GpuSkinning.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <cstddef>
#include <span>
#include <string>

namespace penumbra::render {
namespace {

// skinning.comp's storage blocks.
constexpr std::uint32_t kDeformBinding = 0;
constexpr std::uint32_t kRestBinding = 1;
constexpr std::uint32_t kInfluencesBinding = 2;
constexpr std::uint32_t kTargetsBinding = 3;
constexpr std::uint32_t kJointsBinding = 4;
constexpr std::uint32_t kPosedBinding = 5;

constexpr std::uint32_t kSkinned = 1; // skinning.comp's Deform.flags
constexpr std::uint32_t kFlatNormals = 2;

// Float index of a byte offset into scene::Vertex or a morph target's offsets: the Rest, Targets and Posed buffers hold
// them as flat floats, and the shader reads the fields at these indices.
constexpr std::uint32_t floatIndex(std::size_t byteOffset) { return std::uint32_t(byteOffset / sizeof(float)); }

// One vertex's morph offsets in the Targets buffer: position, normal and tangent xyz, 0 where the target has none.
struct TargetOffsets {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 tangent{0.0f};
};
constexpr std::uint32_t kTargetFloats = floatIndex(sizeof(TargetOffsets));

// The fixed part of skinning.comp's Deform block; the morph weights follow.
struct DeformHeader {
    std::uint32_t vertexCount = 0;
    std::uint32_t influenceSets = 0; // JOINTS_n/WEIGHTS_n sets per vertex
    std::uint32_t targetCount = 0;
    std::uint32_t flags = 0; // kSkinned, kFlatNormals
};

// One element of the Influences block: a vertex's JOINTS_n (into Skin::joints) and WEIGHTS_n.
struct Influence {
    glm::uvec4 joints;
    glm::vec4 weights;
};

// skinning.comp's storage blocks, generated from these declarations. Rest, Targets and Posed are scene::Vertex and
// the morph offsets as floats (the shader's kVertexFloats and kTargetFloats a vertex); Joints a skin's matrices.
constexpr std::array kDeformFields{PENUMBRA_SHADER_FIELD(DeformHeader, vertexCount),
                                   PENUMBRA_SHADER_FIELD(DeformHeader, influenceSets),
                                   PENUMBRA_SHADER_FIELD(DeformHeader, targetCount),
                                   PENUMBRA_SHADER_FIELD(DeformHeader, flags),
                                   shaders::runtimeArrayField<float>("weights", sizeof(DeformHeader))};
constexpr shaders::ShaderStruct kDeformBlock{"Deform", sizeof(DeformHeader), kDeformFields};
constexpr std::array kSkinInfluenceFields{PENUMBRA_SHADER_FIELD(Influence, joints),
                                          PENUMBRA_SHADER_FIELD(Influence, weights)};
constexpr shaders::ShaderStruct kSkinInfluenceStruct{"Influence", sizeof(Influence), kSkinInfluenceFields};
constexpr std::array kInfluencesFields{
    shaders::runtimeStructArrayField<Influence>("influences", 0, kSkinInfluenceStruct)};
constexpr shaders::ShaderStruct kInfluencesBlock{"Influences", 0, kInfluencesFields};
constexpr std::array kRestFields{shaders::runtimeArrayField<float>("rest", 0)};
constexpr shaders::ShaderStruct kRestBlock{"Rest", 0, kRestFields};
constexpr std::array kTargetsFields{shaders::runtimeArrayField<float>("targets", 0)};
constexpr shaders::ShaderStruct kTargetsBlock{"Targets", 0, kTargetsFields};
constexpr std::array kJointsFields{shaders::runtimeArrayField<glm::mat4>("joints", 0)};
constexpr shaders::ShaderStruct kJointsBlock{"Joints", 0, kJointsFields};
constexpr std::array kPosedFields{shaders::runtimeArrayField<float>("posed", 0)};
constexpr shaders::ShaderStruct kPosedBlock{"Posed", 0, kPosedFields};
static_assert(shaders::matchesLayout(kDeformBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kInfluencesBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kRestBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kTargetsBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kJointsBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kPosedBlock, shaders::BlockLayout::Std430));

// Where a storage block reads nothing (a deformer without skin or targets) it is still bound with a few bytes:
// Vulkan refuses an empty range.
constexpr std::size_t kMinimumBytes = 16;

template <typename T>
std::unique_ptr<rhi::Buffer> storage(rhi::Device& device, const std::vector<T>& data, rhi::BufferUsage usage,
                                     const std::string& name)
{
    const std::size_t bytes = std::max(kMinimumBytes, data.size() * sizeof(T));
    auto buffer = device.createBuffer({.size = bytes, .usage = usage, .debugName = name});
    if (!data.empty())
        buffer->write(0, std::as_bytes(std::span(data)));
    return buffer;
}

std::vector<Influence> influencesOf(const scene::Deformer& deformer)
{
    std::vector<Influence> influences(deformer.joints.size());
    for (std::size_t i = 0; i < influences.size(); ++i)
        influences[i] = {deformer.joints[i], deformer.weights[i]};
    return influences;
}

// Each target's offsets per vertex: position, normal and tangent xyz, 0 where the target has none.
std::vector<float> targetsOf(const scene::Deformer& deformer)
{
    const std::size_t vertices = deformer.rest.size();
    std::vector<float> out(deformer.targets.size() * vertices * kTargetFloats, 0.0f);
    for (std::size_t t = 0; t < deformer.targets.size(); ++t) {
        const scene::MorphTarget& target = deformer.targets[t];
        for (std::size_t v = 0; v < vertices; ++v) {
            TargetOffsets offsets;
            offsets.position = target.positions.empty() ? glm::vec3(0.0f) : target.positions[v];
            offsets.normal = target.normals.empty() ? glm::vec3(0.0f) : target.normals[v];
            offsets.tangent = target.tangents.empty() ? glm::vec3(0.0f) : target.tangents[v];
            std::memcpy(&out[(t * vertices + v) * kTargetFloats], &offsets, sizeof(offsets));
        }
    }
    return out;
}

rhi::ShaderSource skinningShader()
{
    using shaders::BlockAccess;
    rhi::ShaderSource source =
        shaders::load("skinning.comp", {{"DEFORM_SKINNED", kSkinned},
                                        {"DEFORM_FLAT_NORMALS", kFlatNormals},
                                        {"VERTEX_FLOATS", floatIndex(sizeof(scene::Vertex))},
                                        {"VERTEX_POSITION", floatIndex(offsetof(scene::Vertex, position))},
                                        {"VERTEX_NORMAL", floatIndex(offsetof(scene::Vertex, normal))},
                                        {"VERTEX_TANGENT", floatIndex(offsetof(scene::Vertex, tangent))},
                                        {"TARGET_FLOATS", kTargetFloats},
                                        {"TARGET_POSITION", floatIndex(offsetof(TargetOffsets, position))},
                                        {"TARGET_NORMAL", floatIndex(offsetof(TargetOffsets, normal))},
                                        {"TARGET_TANGENT", floatIndex(offsetof(TargetOffsets, tangent))}});
    source.includes.push_back(
        {"skinning_blocks.glsl",
         shaders::storageBlockGlsl(kDeformBlock, kDeformBinding, "deform", BlockAccess::ReadOnly) +
             shaders::storageBlockGlsl(kRestBlock, kRestBinding, "", BlockAccess::ReadOnly) +
             shaders::storageBlockGlsl(kInfluencesBlock, kInfluencesBinding, "", BlockAccess::ReadOnly) +
             shaders::storageBlockGlsl(kTargetsBlock, kTargetsBinding, "", BlockAccess::ReadOnly) +
             shaders::storageBlockGlsl(kJointsBlock, kJointsBinding, "", BlockAccess::ReadOnly) +
             shaders::storageBlockGlsl(kPosedBlock, kPosedBinding, "", BlockAccess::WriteOnly)});
    return source;
}

} // namespace

GpuSkinning::GpuSkinning(rhi::Device& device, const GpuScene& scene) : device_(device), scene_(scene)
{
    const scene::Scene& source = scene.scene();
    if (source.rig.deformers.empty())
        return;
    const auto shader = device.createShader(skinningShader());
    pipeline_ = device.createComputePipeline(
        {.compute = shader.get(),
         .storageLayouts = {shaders::storageLayout(kDeformBlock), shaders::storageLayout(kRestBlock),
                            shaders::storageLayout(kInfluencesBlock), shaders::storageLayout(kTargetsBlock),
                            shaders::storageLayout(kJointsBlock), shaders::storageLayout(kPosedBlock)},
         .debugName = "skinning"});
    for (const scene::Deformer& deformer : source.rig.deformers) {
        const std::uint32_t mesh = source.objects.at(deformer.object).mesh;
        const std::string name = fmt::format("mesh {} ({})", mesh, source.objects[deformer.object].name);
        deformers_.push_back(
            {.mesh = mesh,
             .vertexCount = static_cast<std::uint32_t>(deformer.rest.size()),
             .skin = deformer.skin,
             .deform = device.createBuffer({.size = sizeof(DeformHeader) + deformer.targets.size() * sizeof(float),
                                            .usage = rhi::BufferUsage::Storage,
                                            .debugName = name + " pose"}),
             .rest = storage(device, deformer.rest, rhi::BufferUsage::Storage | rhi::BufferUsage::Vertex,
                             name + " rest vertices"),
             .influences = storage(device, influencesOf(deformer), rhi::BufferUsage::Storage, name + " influences"),
             .targets = storage(device, targetsOf(deformer), rhi::BufferUsage::Storage, name + " morph targets")});
    }
    for (const scene::Skin& skin : source.rig.skins)
        joints_.push_back(storage(device, std::vector<glm::mat4>(skin.joints.size()), rhi::BufferUsage::Storage,
                                  "skin '" + skin.name + "' joint matrices"));
}

GpuSkinning::~GpuSkinning() = default;

void GpuSkinning::record(rhi::CommandList& commands)
{
    const scene::Scene& source = scene_.scene();
    const scene::RigPose& pose = source.rig.pose;
    if (pose.joints.size() != source.rig.skins.size() || pose.weights.size() != deformers_.size())
        throw rhi::Error(fmt::format("GPU skinning: the scene's pose holds {} skins and {} deformers of its {} and {} "
                                     "(pose it with scene::poseScene)",
                                     pose.joints.size(), pose.weights.size(), source.rig.skins.size(),
                                     deformers_.size()));
    for (std::size_t s = 0; s < joints_.size(); ++s)
        if (!pose.joints[s].empty())
            joints_[s]->write(0, std::as_bytes(std::span(pose.joints[s])));
    commands.bindComputePipeline(*pipeline_);
    const std::uint32_t groupSize = pipeline_->workgroupSize()[0];
    for (std::size_t d = 0; d < deformers_.size(); ++d) {
        const Deformer& deformer = deformers_[d];
        const scene::Deformer& rest = source.rig.deformers[d];
        const DeformHeader header{.vertexCount = deformer.vertexCount,
                                  .influenceSets = rest.influenceSets,
                                  .targetCount = static_cast<std::uint32_t>(rest.targets.size()),
                                  .flags = (rest.skin >= 0 ? kSkinned : 0) | (rest.flatNormals ? kFlatNormals : 0)};
        deformer.deform->writeObject(header);
        // Missing weights count as 0 (scene::morphVertex).
        std::vector<float> weights(rest.targets.size(), 0.0f);
        std::copy_n(pose.weights[d].begin(), std::min(weights.size(), pose.weights[d].size()), weights.begin());
        if (!weights.empty())
            deformer.deform->write(sizeof(DeformHeader), std::as_bytes(std::span(weights)));
        const rhi::Buffer& joints = deformer.skin >= 0 ? *joints_[std::size_t(deformer.skin)] : *deformer.influences;
        const rhi::Buffer& posed = scene_.vertices(deformer.mesh);
        commands.bindStorageBuffer(kDeformBinding, *deformer.deform, 0, deformer.deform->desc().size);
        commands.bindStorageBuffer(kRestBinding, *deformer.rest, 0, deformer.rest->desc().size);
        commands.bindStorageBuffer(kInfluencesBinding, *deformer.influences, 0, deformer.influences->desc().size);
        commands.bindStorageBuffer(kTargetsBinding, *deformer.targets, 0, deformer.targets->desc().size);
        commands.bindStorageBuffer(kJointsBinding, joints, 0, joints.desc().size);
        commands.bindStorageBuffer(kPosedBinding, posed, 0, posed.desc().size);
        commands.dispatch((deformer.vertexCount + groupSize - 1) / groupSize);
    }
}

std::vector<const rhi::Buffer*> GpuSkinning::posedVertices() const
{
    std::vector<const rhi::Buffer*> buffers;
    for (const Deformer& deformer : deformers_)
        buffers.push_back(&scene_.vertices(deformer.mesh));
    return buffers;
}

const rhi::Buffer* GpuSkinning::restVertices(std::uint32_t mesh) const
{
    for (const Deformer& deformer : deformers_)
        if (deformer.mesh == mesh)
            return deformer.rest.get();
    return nullptr;
}

} // namespace penumbra::render
