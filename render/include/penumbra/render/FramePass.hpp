#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra::render {

class FrameGraph;

// How a pass uses one of the frame's resources, textures and buffers. The graph orders and culls passes by them and
// derives each pass's barriers from them (each stands for one rhi::ResourceState). The first four are for textures
// only, the next four for buffers only, the last four for either.
enum class ResourceUse : std::uint8_t {
    Sampled, // a texture read by shaders through a sampler
    AttachmentRead, // a depth attachment tested but not written (an equal test against the prepass's depth)
    RenderTarget, // drawn into, as a colour or depth attachment
    DrawOver, // drawn into over what an earlier pass left (tiles over cached depth): a read and a write
    VertexRead, // a buffer bound as a vertex buffer (per-vertex or per-instance attributes)
    IndexRead, // a buffer bound as an index buffer
    IndirectRead, // a buffer of indirect draw or dispatch arguments, or of their counts
    UniformRead, // a buffer bound as a uniform block
    StorageRead, // read by shaders as a storage block or image (imageLoad)
    StorageWrite, // written (and read) by a compute shader as a storage block or image (imageStore)
    TransferSource, // read by a copy or a resolve
    TransferDestination, // written by a copy or a resolve
};

constexpr bool writesResource(ResourceUse use)
{
    return use == ResourceUse::RenderTarget || use == ResourceUse::TransferDestination ||
           use == ResourceUse::DrawOver || use == ResourceUse::StorageWrite;
}
constexpr bool readsResource(ResourceUse use) { return use == ResourceUse::DrawOver || !writesResource(use); }
// Whether a texture may have the use; a buffer may have those from VertexRead on.
constexpr bool textureUse(ResourceUse use) { return use < ResourceUse::VertexRead || use >= ResourceUse::StorageRead; }
constexpr bool bufferUse(ResourceUse use) { return use >= ResourceUse::VertexRead; }
const char* resourceUseName(ResourceUse use);

// What a pass tells the graph in FramePass::setup: the frame's textures and buffers it reads and writes, by name
// (FrameResources.hpp names the built-in ones). A pass may touch only what it declared.
class FramePassBuilder {
public:
    // The pass reads `resource`; throws rhi::Error for a name the frame does not know (listing those it does) and for
    // a use its kind of resource cannot have (a buffer sampled, a texture as vertices).
    void read(std::string_view resource, ResourceUse use = ResourceUse::Sampled);
    // The pass writes `resource`; throws as read() does.
    void write(std::string_view resource, ResourceUse use = ResourceUse::RenderTarget);
    // The pass has effects outside the frame's resources (a counter kept elsewhere): the graph never culls it.
    void keep();

private:
    friend class FrameGraph;
    FramePassBuilder(FrameGraph& graph, std::size_t pass) : graph_(graph), pass_(pass) {}

    FrameGraph& graph_;
    std::size_t pass_;
};

// What a pass records with in FramePass::execute.
class FramePassContext {
public:
    // The frame's command list, inside the pass's label.
    rhi::CommandList& commands() const { return commands_; }
    // A texture the pass declared; throws rhi::Error for one it did not.
    const rhi::Texture& texture(std::string_view resource) const;
    // A buffer the pass declared; throws rhi::Error for one it did not, or a resource of several buffers.
    const rhi::Buffer& buffer(std::string_view resource) const;
    // A framebuffer of declared textures (layer 0), made once and kept while they live.
    const rhi::Framebuffer& framebuffer(std::initializer_list<std::string_view> colors,
                                        std::string_view depth = {}) const;

private:
    friend class FrameGraph;
    FramePassContext(FrameGraph& graph, std::size_t pass, rhi::CommandList& commands)
        : graph_(graph), pass_(pass), commands_(commands)
    {
    }

    FrameGraph& graph_;
    std::size_t pass_;
    rhi::CommandList& commands_;
};

// One pass of the frame (Filament's FrameGraph, "addPass(name, setup, execute)", as a class): setup declares what it
// reads and writes this frame and whether it runs; execute records its commands. The graph runs the passes in order,
// leaves out those whose writes nobody reads, labels and times each by its name.
class FramePass {
public:
    virtual ~FramePass() = default;
    // Unique in the frame; what FrameStats::passes, labels and placements name it by.
    virtual std::string name() const = 0;
    // Returns false where the pass does not run this frame (it then declares nothing).
    virtual bool setup(FramePassBuilder& builder) = 0;
    // Records the pass's commands; called only where setup() said it runs and the graph did not cull it.
    virtual void execute(const FramePassContext& context) = 0;
};

// One pass of a frame as it ran: its GPU time where the device has timestamps.
struct PassTiming {
    std::string name;
    std::optional<double> gpuMs;
};

// Where a user's pass goes among the frame's passes: before or after the named one.
struct PassPlacement {
    // Which side of the named pass.
    enum class Side : std::uint8_t { Before, After };
    Side side = Side::After;
    std::string pass;

    // Just before the named pass.
    static PassPlacement before(std::string pass) { return {Side::Before, std::move(pass)}; }
    // Just after the named pass.
    static PassPlacement after(std::string pass) { return {Side::After, std::move(pass)}; }
};

} // namespace penumbra::render
