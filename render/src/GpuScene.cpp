#include "penumbra/render/GpuScene.hpp"

#include "MipLevelsInOrder.hpp"
#include "TextureSampling.hpp"
#include "static/ContentHash.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MipChain.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <cstddef>
#include <cstring>
#include <map>
#include <vector>

namespace penumbra::render {
namespace {

// How a caster's texels enter the atlas (Off: Opaque, for materials whose objects are never listed as casters).
shadows::ShadowCasterMode casterMode(scene::CasterMode mode)
{
    switch (mode) {
    case scene::CasterMode::Clip:
        return shadows::ShadowCasterMode::Clip;
    case scene::CasterMode::Dither:
        return shadows::ShadowCasterMode::Dither;
    case scene::CasterMode::On:
    case scene::CasterMode::Off:
        break;
    }
    return shadows::ShadowCasterMode::Opaque;
}

template <typename T>
std::unique_ptr<rhi::Buffer> upload(rhi::Device& device, const std::vector<T>& data, rhi::BufferUsage usage,
                                    const std::string& name)
{
    auto buffer = device.createBuffer({.size = data.size() * sizeof(T), .usage = usage, .debugName = name});
    buffer->write(0, std::as_bytes(std::span(data)));
    return buffer;
}

std::string debugName(const scene::TextureImage& image) { return "texture '" + image.name + "'"; }

// The texture alpha that the first Clip material reading it as its base colour cuts at (its alphaCutoff over its
// base colour's alpha, which multiplies the texture's): its mip levels keep level 0's alpha-tested coverage
// (rhi::generateMipChain), so leaves do not thin out as they recede (the caster pass reads level 0).
std::optional<float> clipCutoffOf(const scene::Scene& scene, std::uint32_t image)
{
    for (const scene::Material& material : scene.materials) {
        const std::optional<scene::MaterialTexture>& baseColor = material.texture(scene::TextureSlot::BaseColor);
        if (material.caster != scene::CasterMode::Clip || !baseColor || baseColor->image != image)
            continue;
        const float cutoff = material.alphaCutoff / material.baseColor.a;
        return cutoff > 0.0f && cutoff <= 1.0f ? std::optional(cutoff) : std::nullopt;
    }
    return std::nullopt;
}

rhi::TextureDesc textureDesc(const scene::TextureImage& image)
{
    return {.width = image.width,
            .height = image.height,
            .mipLevels = mipLevelsFor(image),
            .format = image.colorSpace == scene::TextureColorSpace::Srgb ? rhi::Format::RGBA8_SRGB : rhi::Format::RGBA8,
            .debugName = debugName(image)};
}

// Levels 1 and below of the texture's chain, with level 0's alpha-tested coverage where a Clip material cuts it.
rhi::MipLevels mipLevelsOf(const scene::Scene& scene, std::size_t index)
{
    const scene::TextureImage& image = scene.textures[index];
    const rhi::TextureDesc desc = textureDesc(image);
    return rhi::generateMipLevels(desc.format, desc.width, desc.height, desc.mipLevels,
                                  std::as_bytes(std::span(image.rgba)), clipCutoffOf(scene, std::uint32_t(index)));
}

// Level 0 is the image's own texels, uploaded as they are.
std::unique_ptr<rhi::Texture> uploadTexture(rhi::Device& device, const scene::TextureImage& image,
                                            const rhi::MipLevels& below)
{
    auto texture = device.createTexture(textureDesc(image));
    device.writeTexture(*texture, 0, 0, std::as_bytes(std::span(image.rgba)));
    for (std::uint32_t level = 1; level < below.levels(); ++level)
        device.writeTexture(*texture, 0, level, below.level(level));
    return texture;
}

} // namespace

GpuScene::GpuScene(rhi::Device& device, const scene::Scene& scene) : scene_(scene), device_(device)
{
    scene.validate();
    // A deformed mesh's vertices are written by the GPU skinning pass (render/src/skinning) every frame.
    std::vector<bool> deformed(scene.meshes.size(), false);
    deformers_.assign(scene.objects.size(), -1);
    std::vector<std::uint32_t> drawnBy(scene.meshes.size(), 0);
    for (const scene::Object& object : scene.objects)
        ++drawnBy[object.mesh];
    for (std::size_t d = 0; d < scene.rig.deformers.size(); ++d) {
        const std::uint32_t object = scene.rig.deformers[d].object;
        const std::uint32_t mesh = scene.objects.at(object).mesh;
        // Objects of one mesh are drawn as instances of one draw: a deformed mesh shared would show one pose for all.
        if (drawnBy[mesh] != 1)
            throw scene::SceneError(fmt::format("object {} ('{}') is deformed (Scene::rig.deformers[{}]), but its mesh "
                                                "{} is drawn by {} objects; a deformed object needs a mesh of its own",
                                                object, scene.objects[object].name, d, mesh, drawnBy[mesh]));
        deformed[mesh] = true;
        deformers_[object] = static_cast<std::int32_t>(d);
        deformedObjects_.push_back(object);
    }
    std::sort(deformedObjects_.begin(), deformedObjects_.end());
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scene::MeshData& mesh = scene.meshes[i];
        const std::string name = "mesh " + std::to_string(i);
        const rhi::BufferUsage usage =
            deformed[i] ? rhi::BufferUsage::Vertex | rhi::BufferUsage::Storage : rhi::BufferUsage::Vertex;
        meshes_.push_back({upload(device, mesh.vertices, usage, name + " vertices"),
                           upload(device, mesh.indices, rhi::BufferUsage::Index, name + " indices")});
    }
    generateMipLevelsInOrder(
        scene.textures.size(), [&](std::size_t i) { return mipLevelsOf(scene, i); },
        [&](std::size_t i, const rhi::MipLevels& below) {
            const scene::TextureImage& image = scene.textures[i];
            textures_.push_back(uploadTexture(device, image, below));
            samplers_.push_back(device.createSampler(samplerDesc(image.sampler, anisotropy_, debugName(image))));
            coverageSamplers_.push_back(
                device.createSampler(samplerDesc(image.sampler, 1.0f, debugName(image) + " (coverage)")));
        });
    const scene::TextureImage white{.name = "white texel",
                                    .width = 1,
                                    .height = 1,
                                    .rgba = {255, 255, 255, 255},
                                    .sampler = {.mipFilter = scene::TextureMipFilter::None}};
    white_ = uploadTexture(device, white, rhi::MipLevels{});
    whiteSampler_ = device.createSampler(samplerDesc(white.sampler, 1.0f, debugName(white)));
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> groups;
    for (const scene::Object& object : scene.objects)
        meshMaterialGroups_.push_back(
            groups.try_emplace({object.mesh, object.material}, static_cast<std::uint32_t>(groups.size()))
                .first->second);
    refresh({});
}

std::uint32_t GpuScene::litDrawGroup(std::uint32_t object) const
{
    return meshMaterialGroups_.at(object) * 2 + (scene_.receivesShadows(scene_.objects[object]) ? 1 : 0);
}

const rhi::Texture& GpuScene::texture(std::optional<std::uint32_t> index) const
{
    return index ? *textures_.at(*index) : *white_;
}

const rhi::Sampler& GpuScene::sampler(std::optional<std::uint32_t> index) const
{
    return index ? *samplers_.at(*index) : *whiteSampler_;
}

const rhi::Texture& GpuScene::map(const scene::Material& material, scene::TextureSlot slot) const
{
    const std::optional<scene::MaterialTexture>& texture = material.texture(slot);
    return this->texture(texture ? std::optional(texture->image) : std::nullopt);
}

const rhi::Sampler& GpuScene::mapSampler(const scene::Material& material, scene::TextureSlot slot) const
{
    const std::optional<scene::MaterialTexture>& texture = material.texture(slot);
    return sampler(texture ? std::optional(texture->image) : std::nullopt);
}

const rhi::Sampler& GpuScene::coverageSampler(const scene::Material& material) const
{
    const std::optional<scene::MaterialTexture>& texture = material.texture(scene::TextureSlot::BaseColor);
    return texture ? *coverageSamplers_.at(texture->image) : *whiteSampler_;
}

void GpuScene::setMaxAnisotropy(float anisotropy)
{
    if (anisotropy == anisotropy_)
        return;
    anisotropy_ = anisotropy;
    for (std::size_t i = 0; i < samplers_.size(); ++i)
        samplers_[i] =
            device_.createSampler(samplerDesc(scene_.textures[i].sampler, anisotropy_, debugName(scene_.textures[i])));
}

shadows::UvTransformRows GpuScene::uvTransform(const std::optional<scene::MaterialTexture>& texture)
{
    return texture ? shadows::uvTransformRows(texture->transform.matrix(), texture->texCoord)
                   : shadows::uvTransformRows(glm::mat3(1.0f), 0);
}

shadows::ShadowCaster GpuScene::materialCaster(const scene::Material& material) const
{
    const std::optional<scene::MaterialTexture>& baseColor = material.texture(scene::TextureSlot::BaseColor);
    shadows::ShadowCaster caster;
    caster.mode = casterMode(material.caster);
    caster.alpha = material.baseColor.a;
    caster.alphaCutoff = material.alphaCutoff;
    caster.baseColorMap = &baseColorMap(material);
    caster.baseColorSampler = &coverageSampler(material);
    caster.textured = baseColor.has_value();
    caster.baseColorUv = uvTransform(baseColor);
    caster.doubleSided = material.doubleSided;
    return caster;
}

bool GpuScene::materialsChanged() const
{
    bool changed = materialCasters_.size() != scene_.materials.size();
    materialCasters_.resize(scene_.materials.size());
    materialKeys_.resize(scene_.materials.size());
    for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
        const scene::Material& material = scene_.materials[m];
        const shadows::ShadowCaster caster = materialCaster(material);
        const MaterialKey key{material.caster, material.blend, material.receiveShadows};
        if (key != materialKeys_[m] || !shadows::drawAlike(caster, materialCasters_[m])) {
            changed = true;
            materialCasters_[m] = caster;
            materialKeys_[m] = key;
        }
    }
    return changed;
}

void GpuScene::rebuildCasters(const CasterOptions& options) const
{
    casters_.clear();
    casterBounds_.clear();
    staticCasters_.clear();
    snapshots_.resize(scene_.objects.size());
    casterOf_.assign(scene_.objects.size(), kNoCaster);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        const scene::Object& object = scene_.objects[i];
        snapshots_[i] = {object.transform, object.worldBounds, object.castShadows, object.receiveShadows,
                         object.mobility};
        if (!scene_.castsShadows(object))
            continue;
        const auto index = static_cast<std::uint32_t>(casters_.size());
        casterOf_[i] = index;
        shadows::ShadowCaster& caster = casters_.emplace_back(materialCasters_.at(object.material));
        const rhi::Buffer* vertices = object.mesh < options.vertices.size() ? options.vertices[object.mesh] : nullptr;
        caster.vertices = vertices ? vertices : meshes_[object.mesh].vertices.get();
        caster.indices = meshes_[object.mesh].indices.get();
        caster.indexCount = static_cast<std::uint32_t>(scene_.meshOf(object).indices.size());
        caster.model = object.transform;
        caster.pose = poseKey(i);
        caster.doubleSided = caster.doubleSided || object.castShadows == scene::ShadowCasting::TwoSided;
        caster.drawGroup =
            options.instancedDraws ? meshMaterialGroups_[i] * 2 + (caster.doubleSided ? 1 : 0) : shadows::kNoDrawGroup;
        casterBounds_.push_back({object.worldBounds.min, object.worldBounds.max});
        if (object.mobility == scene::Mobility::Static)
            staticCasters_.push_back(index);
    }
    casterChanges_.changedAll();
    objectChanges_.changedAll();
}

bool GpuScene::compareObjects(std::size_t first, std::size_t end, bool reported) const
{
    for (std::size_t i = first; i < end; ++i) {
        const scene::Object& object = scene_.objects[i];
        ObjectSnapshot& kept = snapshots_[i];
        const bool kindChanged = object.castShadows != kept.castShadows ||
                                 object.receiveShadows != kept.receiveShadows || object.mobility != kept.mobility;
        // Bit for bit, which is faster than float by float over 10^5 objects, and counts a NaN that stays as unchanged.
        const bool moved = std::memcmp(&object.transform, &kept.transform, sizeof(glm::mat4)) != 0 ||
                           std::memcmp(&object.worldBounds, &kept.worldBounds, sizeof(scene::Bounds)) != 0;
        if (!kindChanged && !moved)
            continue;
        if (!reported)
            throw rhi::Error(
                fmt::format("GpuScene: object {} ('{}') was edited in place (its transform, world bounds, "
                            "shadow casting or receiving, or mobility) without scene::Scene::revision "
                            "being raised; raise it after editing, so the renderer reads the objects again",
                            i, object.name));
        if (kindChanged)
            return true;
        kept.transform = object.transform;
        kept.worldBounds = object.worldBounds;
        objectChanges_.changed(static_cast<std::uint32_t>(i));
        const std::uint32_t caster = casterOf_[i];
        if (caster == kNoCaster)
            continue;
        casters_[caster].model = object.transform;
        casterBounds_[caster] = {object.worldBounds.min, object.worldBounds.max};
        casterChanges_.changed(caster);
    }
    return false;
}

void GpuScene::refresh(const CasterOptions& options) const
{
    const std::vector<scene::Object>& objects = scene_.objects;
    if (objects.size() != meshMaterialGroups_.size())
        throw rhi::Error(fmt::format("GpuScene: the scene has {} objects, but {} were uploaded; objects cannot be "
                                     "added or removed after the upload",
                                     objects.size(), meshMaterialGroups_.size()));
    // Both run: materialsChanged() keeps the materials' casters that a rebuild copies.
    bool rebuild = materialsChanged();
    rebuild = !options_ || *options_ != options || rebuild;
    if (!rebuild && revision_ != scene_.revision) {
        rebuild = compareObjects(0, objects.size(), true);
    } else if (!rebuild && !objects.empty()) {
        // The next kSpotChecks objects in turn, wrapping round.
        const std::size_t first = spotCheck_ < objects.size() ? spotCheck_ : 0;
        const std::size_t end = std::min(objects.size(), first + kSpotChecks);
        compareObjects(first, end, false);
        spotCheck_ = end;
    }
    revision_ = scene_.revision;
    if (rebuild) {
        options_ = options;
        rebuildCasters(options);
    } else {
        for (const std::uint32_t object : deformedObjects_) {
            const std::uint32_t caster = casterOf_[object];
            if (caster == kNoCaster)
                continue;
            const std::uint64_t pose = poseKey(object);
            if (casters_[caster].pose != pose) {
                casters_[caster].pose = pose;
                casterChanges_.changed(caster);
            }
        }
    }
    casterChanges_.advance();
    objectChanges_.advance();
}

std::uint64_t GpuScene::poseKey(std::size_t object) const
{
    const std::int32_t deformer = deformers_.at(object);
    const scene::RigPose& pose = scene_.rig.pose;
    if (deformer < 0 || std::size_t(deformer) >= pose.weights.size())
        return 0;
    ContentHash hash;
    const std::int32_t skin = scene_.rig.deformers[std::size_t(deformer)].skin;
    if (skin >= 0)
        for (const glm::mat4& joint : pose.joints.at(std::size_t(skin)))
            hash.add(joint);
    for (const float weight : pose.weights[std::size_t(deformer)])
        hash.add(weight);
    return hash.value();
}

shadows::CasterVertexFormat GpuScene::vertexFormat()
{
    return {sizeof(scene::Vertex), offsetof(scene::Vertex, position), offsetof(scene::Vertex, normal),
            offsetof(scene::Vertex, uv), offsetof(scene::Vertex, uv1)};
}

rhi::VertexLayout GpuScene::vertexLayout()
{
    const auto offset = [](std::size_t bytes) { return static_cast<std::uint32_t>(bytes); };
    rhi::VertexLayout layout{{{sizeof(scene::Vertex), false}},
                             {{0, rhi::VertexFormat::Float3, offset(offsetof(scene::Vertex, position)), 0},
                              {1, rhi::VertexFormat::Float3, offset(offsetof(scene::Vertex, normal)), 0},
                              {2, rhi::VertexFormat::Float2, offset(offsetof(scene::Vertex, uv)), 0},
                              {3, rhi::VertexFormat::Float2, offset(offsetof(scene::Vertex, uv1)), 0},
                              {4, rhi::VertexFormat::Float4, offset(offsetof(scene::Vertex, tangent)), 0},
                              {5, rhi::VertexFormat::Float4, offset(offsetof(scene::Vertex, color)), 0}}};
    shadows::addInstanceAttributes(layout, shadows::kInstanceSlot);
    return layout;
}

void GpuScene::bindWithMaps(rhi::CommandList& commands, const scene::Object& object, std::uint32_t firstMapBinding,
                            std::uint32_t coverageBinding, const rhi::BufferSlice& instances) const
{
    const scene::Material& material = scene_.materialOf(object);
    for (std::uint32_t slot = 0; slot < scene::kTextureSlots; ++slot) {
        const auto textureSlot = static_cast<scene::TextureSlot>(slot);
        commands.bindTexture(firstMapBinding + slot, map(material, textureSlot), mapSampler(material, textureSlot));
    }
    commands.bindTexture(coverageBinding, baseColorMap(material), coverageSampler(material));
    commands.bindVertexBuffer(0, vertices(object.mesh));
    commands.bindVertexBuffer(shadows::kInstanceSlot, *instances.buffer, instances.offset);
    commands.bindIndexBuffer(indices(object.mesh), rhi::IndexType::UInt32);
}

void GpuScene::drawWithMaps(rhi::CommandList& commands, const scene::Object& object, std::uint32_t firstMapBinding,
                            std::uint32_t coverageBinding, const rhi::BufferSlice& instances,
                            std::uint32_t instanceCount) const
{
    bindWithMaps(commands, object, firstMapBinding, coverageBinding, instances);
    commands.drawIndexed(static_cast<std::uint32_t>(scene_.meshOf(object).indices.size()), instanceCount);
}

} // namespace penumbra::render
