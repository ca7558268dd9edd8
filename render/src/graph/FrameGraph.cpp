#include "FrameGraph.hpp"

#include "PassBarriers.hpp"
#include "TransientSlots.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_map>

namespace penumbra::render {
namespace {

// Textures that may share memory: everything but the debug name alike.
std::string textureKey(const rhi::TextureDesc& d)
{
    return fmt::format("{}x{}x{} a{} c{} m{} f{} u{} s{}", d.width, d.height, d.layers, d.array, d.cube, d.mipLevels,
                       static_cast<int>(d.format), static_cast<int>(d.usage), d.samples);
}

// The RHI's state for a declared use.
rhi::ResourceState graphUseState(ResourceUse use)
{
    using rhi::ResourceState;
    switch (use) {
    case ResourceUse::Sampled:
    case ResourceUse::StorageRead:
        return ResourceState::ShaderRead;
    case ResourceUse::AttachmentRead:
        return ResourceState::DepthRead;
    case ResourceUse::RenderTarget:
    case ResourceUse::DrawOver:
        return ResourceState::RenderTarget;
    case ResourceUse::VertexRead:
        return ResourceState::VertexBuffer;
    case ResourceUse::IndexRead:
        return ResourceState::IndexBuffer;
    case ResourceUse::IndirectRead:
        return ResourceState::IndirectArgument;
    case ResourceUse::UniformRead:
        return ResourceState::UniformBuffer;
    case ResourceUse::StorageWrite:
        return ResourceState::ShaderWrite;
    case ResourceUse::TransferSource:
        return ResourceState::CopySource;
    case ResourceUse::TransferDestination:
        break;
    }
    return ResourceState::CopyDestination;
}

// How a message names a resource a use is declared for.
const char* useResourceKind(ResourceUse use)
{
    if (!bufferUse(use))
        return "texture";
    return textureUse(use) ? "resource" : "buffer";
}

} // namespace

const char* resourceUseName(ResourceUse use)
{
    switch (use) {
    case ResourceUse::Sampled:
        return "sampled";
    case ResourceUse::AttachmentRead:
        return "attachment read";
    case ResourceUse::RenderTarget:
        return "render target";
    case ResourceUse::DrawOver:
        return "drawn over";
    case ResourceUse::VertexRead:
        return "vertex read";
    case ResourceUse::IndexRead:
        return "index read";
    case ResourceUse::IndirectRead:
        return "indirect read";
    case ResourceUse::UniformRead:
        return "uniform read";
    case ResourceUse::StorageRead:
        return "storage read";
    case ResourceUse::StorageWrite:
        return "storage write";
    case ResourceUse::TransferSource:
        return "transfer source";
    case ResourceUse::TransferDestination:
        return "transfer destination";
    }
    return "?";
}

void FramePassBuilder::read(std::string_view resource, ResourceUse use)
{
    if (!readsResource(use) || writesResource(use))
        throw rhi::Error(fmt::format("frame graph: pass '{}' reads '{}' as a {}, which is a write",
                                     graph_.passes_[pass_].name, resource, resourceUseName(use)));
    graph_.declare(pass_, resource, use);
}

void FramePassBuilder::write(std::string_view resource, ResourceUse use)
{
    if (!writesResource(use))
        throw rhi::Error(fmt::format("frame graph: pass '{}' writes '{}' as a {}, which is a read",
                                     graph_.passes_[pass_].name, resource, resourceUseName(use)));
    graph_.declare(pass_, resource, use);
}

void FramePassBuilder::keep() { graph_.passes_[pass_].kept = true; }

const rhi::Texture& FramePassContext::texture(std::string_view resource) const
{
    return *graph_.declared(pass_, resource, false).texture;
}

const rhi::Buffer& FramePassContext::buffer(std::string_view resource) const
{
    const std::vector<const rhi::Buffer*>& buffers = graph_.declared(pass_, resource, true).buffers;
    if (buffers.size() != 1)
        throw rhi::Error(fmt::format("frame graph: pass '{}' asks for buffer '{}', which holds {} buffers",
                                     graph_.passes_[pass_].name, resource, buffers.size()));
    return *buffers.front();
}

const rhi::Framebuffer& FramePassContext::framebuffer(std::initializer_list<std::string_view> colors,
                                                      std::string_view depth) const
{
    return graph_.framebuffer(pass_, colors, depth);
}

FrameGraph::FrameGraph(rhi::Device& device) : device_(device) {}

FrameGraph::~FrameGraph() = default;

void FrameGraph::reset()
{
    passes_.clear();
    resources_.clear();
    timed_.clear();
}

void FrameGraph::addResource(Resource resource)
{
    if (resourceIndex(resource.name) != resources_.size())
        throw rhi::Error(fmt::format("frame graph: resource '{}' declared twice", resource.name));
    resources_.push_back(std::move(resource));
}

void FrameGraph::importTexture(std::string_view name, const rhi::Texture& texture, bool output)
{
    addResource({.name = std::string(name), .texture = &texture, .output = output});
}

void FrameGraph::createTexture(std::string_view name, const rhi::TextureDesc& desc)
{
    addResource({.name = std::string(name), .transient = desc});
}

void FrameGraph::importBuffers(std::string_view name, std::vector<const rhi::Buffer*> buffers, bool output)
{
    addResource({.name = std::string(name), .output = output, .isBuffer = true, .buffers = std::move(buffers)});
}

void FrameGraph::addPass(FramePass& pass)
{
    std::string name = pass.name();
    if (std::any_of(passes_.begin(), passes_.end(), [&](const Pass& p) { return p.name == name; }))
        throw rhi::Error(fmt::format("frame graph: two passes are named '{}'", name));
    passes_.push_back({&pass, std::move(name)});
}

std::size_t FrameGraph::resourceIndex(std::string_view name) const
{
    return static_cast<std::size_t>(
        std::find_if(resources_.begin(), resources_.end(), [&](const Resource& r) { return r.name == name; }) -
        resources_.begin());
}

void FrameGraph::declare(std::size_t pass, std::string_view resource, ResourceUse use)
{
    const std::size_t index = resourceIndex(resource);
    if (index == resources_.size()) {
        std::string known;
        for (const Resource& r : resources_)
            known += fmt::format("{}'{}'", known.empty() ? "" : ", ", r.name);
        throw rhi::Error(fmt::format("frame graph: pass '{}' uses {} '{}', which the frame does not have ({})",
                                     passes_[pass].name, useResourceKind(use), resource, known));
    }
    const bool isBuffer = resources_[index].isBuffer;
    if (isBuffer ? !bufferUse(use) : !textureUse(use))
        throw rhi::Error(fmt::format("frame graph: pass '{}' uses {} '{}' as {}, a use of {} only", passes_[pass].name,
                                     isBuffer ? "buffer" : "texture", resource, resourceUseName(use),
                                     isBuffer ? "textures" : "buffers"));
    passes_[pass].uses.push_back({index, use});
}

void FrameGraph::compile()
{
    for (std::size_t i = 0; i < passes_.size(); ++i) {
        FramePassBuilder builder(*this, i);
        passes_[i].runs = passes_[i].pass->setup(builder);
        if (!passes_[i].runs)
            passes_[i].uses.clear();
    }
    checkOrder();
    cull();
    makeTransients();
}

// A made texture holds nothing before its first write.
void FrameGraph::checkOrder() const
{
    std::vector<bool> written(resources_.size());
    for (std::size_t r = 0; r < resources_.size(); ++r)
        written[r] = !resources_[r].transient;
    for (const Pass& pass : passes_) {
        for (const Use& use : pass.uses)
            if (readsResource(use.use) && !written[use.resource])
                throw rhi::Error(fmt::format("frame graph: pass '{}' reads '{}' before any pass writes it", pass.name,
                                             resources_[use.resource].name));
        for (const Use& use : pass.uses)
            if (writesResource(use.use))
                written[use.resource] = true;
    }
}

// Backwards from the outputs: a pass runs when one of its writes is needed later (an output, or a later running
// pass's read), or when it keep()s; its reads are then needed before it. Writes stay needed, as a pass may write part
// of a texture (one tile of an atlas) and leave the rest to an earlier pass.
void FrameGraph::cull()
{
    std::vector<bool> needed(resources_.size());
    for (std::size_t r = 0; r < resources_.size(); ++r)
        needed[r] = resources_[r].output;
    for (auto pass = passes_.rbegin(); pass != passes_.rend(); ++pass) {
        if (!pass->runs)
            continue;
        pass->culled = !pass->kept && std::none_of(pass->uses.begin(), pass->uses.end(), [&](const Use& use) {
            return writesResource(use.use) && needed[use.resource];
        });
        if (pass->culled)
            continue;
        for (const Use& use : pass->uses)
            if (readsResource(use.use))
                needed[use.resource] = true;
    }
}

void FrameGraph::makeTransients()
{
    std::vector<std::size_t> transients;
    std::vector<TransientLifetime> lifetimes;
    std::vector<std::string> keys;
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        if (!resources_[r].transient)
            continue;
        std::optional<std::size_t> first, last;
        for (std::size_t p = 0; p < passes_.size(); ++p) {
            const Pass& pass = passes_[p];
            if (!pass.runs || pass.culled ||
                std::none_of(pass.uses.begin(), pass.uses.end(), [&](const Use& u) { return u.resource == r; }))
                continue;
            first = first.value_or(p);
            last = p;
        }
        if (!first)
            continue; // no pass that runs uses it
        const std::string key = textureKey(*resources_[r].transient);
        const auto kind = static_cast<std::size_t>(std::find(keys.begin(), keys.end(), key) - keys.begin());
        if (kind == keys.size())
            keys.push_back(key);
        transients.push_back(r);
        lifetimes.push_back({kind, *first, *last});
    }
    const std::vector<std::uint32_t> slots = assignTransientSlots(lifetimes);
    // The pool keeps, per description, as many textures as this frame's slots: a description the frame no longer
    // uses, or a slot beyond its count, is freed.
    std::map<std::string, std::vector<std::unique_ptr<rhi::Texture>>> pool;
    for (std::size_t i = 0; i < transients.size(); ++i) {
        Resource& resource = resources_[transients[i]];
        const std::string& key = keys[lifetimes[i].kind];
        std::vector<std::unique_ptr<rhi::Texture>>& textures = pool[key];
        std::vector<std::unique_ptr<rhi::Texture>>& previous = pool_[key];
        if (textures.size() <= slots[i])
            textures.resize(slots[i] + 1);
        if (!textures[slots[i]] && slots[i] < previous.size())
            textures[slots[i]] = std::move(previous[slots[i]]);
        if (!textures[slots[i]]) {
            rhi::TextureDesc desc = *resource.transient;
            desc.debugName = fmt::format("frame graph: {}", resource.name);
            textures[slots[i]] = device_.createTexture(desc);
            dropFramebuffers();
        }
        resource.texture = textures[slots[i]].get();
    }
    const bool freed = std::any_of(pool_.begin(), pool_.end(), [](const auto& entry) {
        return std::any_of(entry.second.begin(), entry.second.end(), [](const auto& t) { return t != nullptr; });
    });
    if (freed)
        dropFramebuffers();
    pool_ = std::move(pool);
}

const FrameGraph::Resource& FrameGraph::declared(std::size_t pass, std::string_view resource, bool buffer) const
{
    const std::size_t index = resourceIndex(resource);
    const std::vector<Use>& uses = passes_[pass].uses;
    if (index == resources_.size() ||
        std::none_of(uses.begin(), uses.end(), [&](const Use& u) { return u.resource == index; }))
        throw rhi::Error(fmt::format("frame graph: pass '{}' did not declare {} '{}' in its setup", passes_[pass].name,
                                     buffer ? "buffer" : "texture", resource));
    if (resources_[index].isBuffer != buffer)
        throw rhi::Error(fmt::format("frame graph: pass '{}' asks for {} '{}', which is a {}", passes_[pass].name,
                                     buffer ? "buffer" : "texture", resource, buffer ? "texture" : "buffer"));
    return resources_[index];
}

const rhi::Framebuffer& FrameGraph::framebuffer(std::size_t pass, std::initializer_list<std::string_view> colors,
                                                std::string_view depth)
{
    std::vector<const rhi::Texture*> key;
    std::vector<rhi::Attachment> attachments;
    for (std::string_view color : colors) {
        key.push_back(declared(pass, color, false).texture);
        attachments.push_back({key.back(), 0});
    }
    key.push_back(nullptr); // the colours end
    const rhi::Texture* depthTexture = depth.empty() ? nullptr : declared(pass, depth, false).texture;
    key.push_back(depthTexture);
    std::unique_ptr<rhi::Framebuffer>& framebuffer = framebuffers_[key];
    if (!framebuffer)
        framebuffer = device_.createFramebuffer({.colors = attachments,
                                                 .depth = {depthTexture, 0},
                                                 .debugName = fmt::format("frame graph: {}", passes_[pass].name)});
    return *framebuffer;
}

void FrameGraph::execute(rhi::CommandList& commands)
{
    timed_.clear();
    for (std::size_t p = 0; p < passes_.size(); ++p)
        if (passes_[p].runs && !passes_[p].culled)
            timed_.push_back(p);
    // As many queries as this frame writes: a query not written is never read (Vulkan 1.3 section 17.2).
    const auto queries = static_cast<std::uint32_t>(timed_.size() + 1);
    if (device_.capabilities().timestamps && (!timestamps_ || timestamps_->count() != queries))
        timestamps_ = device_.createTimestampQueries(queries);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 0);
    const std::vector<std::vector<rhi::ResourceBarrier>> barriers = timedBarriers();
    for (std::size_t i = 0; i < timed_.size(); ++i) {
        const FramePassContext context(*this, timed_[i], commands);
        commands.pushLabel(passes_[timed_[i]].name);
        commands.resourceBarriers(barriers[i]);
        passes_[timed_[i]].pass->execute(context);
        commands.popLabel();
        if (timestamps_)
            commands.writeTimestamp(*timestamps_, static_cast<std::uint32_t>(i + 1));
    }
}

std::vector<std::vector<rhi::ResourceBarrier>> FrameGraph::timedBarriers() const
{
    std::vector<std::vector<ObjectUse>> uses;
    std::unordered_map<const void*, rhi::ResourceBarrier> objects; // each texture and buffer, as a barrier names it
    for (const std::size_t pass : timed_) {
        std::vector<ObjectUse>& passUses = uses.emplace_back();
        for (const Use& use : passes_[pass].uses) {
            const Resource& resource = resources_[use.resource];
            const rhi::ResourceState state = graphUseState(use.use);
            if (resource.texture) {
                passUses.push_back({resource.texture, state});
                objects.try_emplace(resource.texture, rhi::ResourceBarrier{.texture = resource.texture});
            }
            for (const rhi::Buffer* buffer : resource.buffers) {
                passUses.push_back({buffer, state});
                objects.try_emplace(buffer, rhi::ResourceBarrier{.buffer = buffer});
            }
        }
    }
    std::vector<std::vector<rhi::ResourceBarrier>> barriers;
    for (const std::vector<StateChange>& changes : passBarriers(uses)) {
        std::vector<rhi::ResourceBarrier>& batch = barriers.emplace_back();
        for (const StateChange& change : changes) {
            rhi::ResourceBarrier barrier = objects.at(change.object);
            barrier.before = change.before;
            barrier.after = change.after;
            batch.push_back(barrier);
        }
    }
    return barriers;
}

std::vector<PassTiming> FrameGraph::timings()
{
    std::vector<PassTiming> timings;
    std::vector<double> ns;
    if (timestamps_ && !timed_.empty())
        ns = device_.readTimestamps(*timestamps_);
    for (std::size_t i = 0; i < timed_.size(); ++i) {
        PassTiming timing{passes_[timed_[i]].name, std::nullopt};
        if (!ns.empty())
            timing.gpuMs = (ns[i + 1] - ns[i]) * 1e-6;
        timings.push_back(std::move(timing));
    }
    return timings;
}

} // namespace penumbra::render
