// The explicit barriers' rules (CommandList::resourceBarriers) and the check that every access a list records is
// among the uses its barriers declared.

#include "penumbra/rhi/ValidatingDevice.hpp"

#include "Rules.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

const void* barrierResource(const ResourceBarrier& b)
{
    return b.texture ? static_cast<const void*>(b.texture) : static_cast<const void*>(b.buffer);
}

std::string barrierResourceName(const Texture* texture, const Buffer* buffer)
{
    return texture ? fmt::format("texture '{}'", texture->desc().debugName)
                   : fmt::format("buffer '{}'", buffer->desc().debugName);
}

// The usages each state needs: on a texture, on a buffer ("" where the state is not one of that kind of resource).
struct StateUsage {
    ResourceState state;
    TextureUsage texture; // None: any texture may (copies), or none may (buffer states), as `textureAllowed` says
    bool textureAllowed;
    BufferUsage buffer;
    bool bufferAllowed;
    const char* usageNames; // what the message names
};

constexpr StateUsage kStateUsages[] = {
    {ResourceState::VertexBuffer, TextureUsage::None, false, BufferUsage::Vertex, true, "BufferUsage::Vertex"},
    {ResourceState::IndexBuffer, TextureUsage::None, false, BufferUsage::Index, true, "BufferUsage::Index"},
    {ResourceState::IndirectArgument, TextureUsage::None, false, BufferUsage::Indirect, true, "BufferUsage::Indirect"},
    {ResourceState::UniformBuffer, TextureUsage::None, false, BufferUsage::Uniform, true, "BufferUsage::Uniform"},
    {ResourceState::ShaderRead, TextureUsage::Sampled | TextureUsage::Storage, true, BufferUsage::Storage, true,
     "TextureUsage::Sampled or Storage, or BufferUsage::Storage"},
    {ResourceState::ShaderWrite, TextureUsage::Storage, true, BufferUsage::Storage, true,
     "TextureUsage::Storage or BufferUsage::Storage"},
    {ResourceState::RenderTarget, TextureUsage::RenderTarget, true, BufferUsage{}, false, "TextureUsage::RenderTarget"},
    {ResourceState::DepthRead, TextureUsage::RenderTarget, true, BufferUsage{}, false, "TextureUsage::RenderTarget"},
};

void checkBarrierUsage(const ResourceBarrier& b, const std::string& name)
{
    for (const StateUsage& u : kStateUsages) {
        if (!hasFlag(b.after, u.state))
            continue;
        const bool allowed = b.texture ? u.textureAllowed && hasFlag(b.texture->desc().usage, u.texture)
                                       : u.bufferAllowed && hasFlag(b.buffer->desc().usage, u.buffer);
        if (!allowed)
            throw Error(fmt::format("resourceBarriers: {} cannot be in state {}, which needs {}", name,
                                    resourceStateName(u.state), u.usageNames));
    }
    if (hasFlag(b.after, ResourceState::DepthRead) && !isDepthFormat(b.texture->desc().format))
        throw Error(fmt::format("resourceBarriers: {} cannot be in state DepthRead: {} is not a depth format", name,
                                formatName(b.texture->desc().format)));
}

} // namespace

void checkResourceBarrier(const ResourceBarrier& b, ResourceState declared)
{
    if ((b.texture != nullptr) == (b.buffer != nullptr))
        throw Error(fmt::format("resourceBarriers: a barrier names {}; name one texture or one buffer",
                                b.texture ? "a texture and a buffer" : "no resource"));
    const std::string name = barrierResourceName(b.texture, b.buffer);
    if (b.after == ResourceState::Undefined)
        throw Error(
            fmt::format("resourceBarriers: {} goes to state Undefined; name the state it is used in next", name));
    checkBarrierUsage(b, name);
    if (b.before != declared)
        throw Error(fmt::format("resourceBarriers: {} leaves state {}, but the list last declared {}", name,
                                resourceStateName(b.before), resourceStateName(declared)));
}

void ValidatingCommandList::resourceBarriers(std::span<const ResourceBarrier> barriers)
{
    if (validate_) {
        requireOutsidePass("resourceBarriers");
        for (std::size_t i = 0; i < barriers.size(); ++i) {
            checkResourceBarrier(barriers[i], hazards_.declared(barrierResource(barriers[i])));
            for (std::size_t j = 0; j < i; ++j)
                if (barrierResource(barriers[j]) == barrierResource(barriers[i]))
                    throw Error(fmt::format("resourceBarriers: {} has two barriers in one call; merge their states",
                                            barrierResourceName(barriers[i].texture, barriers[i].buffer)));
        }
        drawChecked_ = false;
    }
    record(hazards_.declare(barriers, labels_.empty() ? std::string() : labels_.back(), labels_.size()));
}

void ValidatingCommandList::checkDeclared(std::string_view what, const Texture* texture, const Buffer* buffer,
                                          ResourceState needed, std::string_view how) const
{
    const void* resource = texture ? static_cast<const void*>(texture) : static_cast<const void*>(buffer);
    if (!resource || hazards_.covers(resource, needed))
        return;
    const std::string& pass = hazards_.scopePass();
    const ResourceState scoped = hazards_.scoped(resource);
    const std::string declared = scoped == ResourceState::Undefined
                                     ? std::string("do not declare it")
                                     : fmt::format("declare it {} only", resourceStateName(scoped));
    const std::string used =
        fmt::format("{} as {} ({})", barrierResourceName(texture, buffer), resourceStateName(needed), how);
    if (pass.empty())
        throw Error(fmt::format("{}: uses {}, but the last resourceBarriers {}", what, used, declared));
    throw Error(fmt::format("{}: pass '{}' uses {}, but its resourceBarriers {}", what, pass, used, declared));
}

void ValidatingCommandList::checkDeclaredBindings(std::string_view what,
                                                  const std::vector<ShaderBinding>& bindings) const
{
    for (const ShaderBinding& b : bindings) {
        if (b.binding >= resources_.size())
            continue;
        const Resource& r = resources_[b.binding];
        ResourceState needed = ResourceState::ShaderRead;
        if (b.kind == BindingKind::UniformBuffer)
            needed = ResourceState::UniformBuffer;
        else if (b.writes)
            needed = ResourceState::ShaderWrite;
        if (!hazards_.covers(r.object, needed))
            checkDeclared(what, r.texture, r.buffer, needed, fmt::format("binding {}, '{}'", b.binding, b.name));
    }
}

void ValidatingCommandList::checkDeclaredVertices(std::string_view what) const
{
    for (const VertexAttribute& a : pipeline_->desc().vertexLayout.attributes)
        if (!hazards_.covers(vertexBuffers_[a.buffer], ResourceState::VertexBuffer))
            checkDeclared(what, nullptr, vertexBuffers_[a.buffer], ResourceState::VertexBuffer,
                          fmt::format("vertex buffer slot {}", a.buffer));
}

} // namespace penumbra::rhi
