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

// How a pass uses one of the frame's textures. The first three read, the last four write (DrawOver reads too); the
// graph orders and culls passes by them (and, as the RHI learns explicit barriers, derives those from them).
enum class ResourceUse : std::uint8_t {
    Sampled, // read by shaders
    AttachmentRead, // a depth attachment tested but not written (an equal test against the prepass's depth)
    TransferSource, // read by a copy or a resolve
    RenderTarget, // drawn into, as a colour or depth attachment
    TransferDestination, // written by a copy or a resolve
    DrawOver, // drawn into over what an earlier pass left (tiles over cached depth): a read and a write
    StorageWrite, // written by a compute shader as a storage image (imageStore)
};

constexpr bool readsResource(ResourceUse use)
{
    return use != ResourceUse::RenderTarget && use != ResourceUse::TransferDestination &&
           use != ResourceUse::StorageWrite;
}
constexpr bool writesResource(ResourceUse use)
{
    return use == ResourceUse::RenderTarget || use == ResourceUse::TransferDestination ||
           use == ResourceUse::DrawOver || use == ResourceUse::StorageWrite;
}
const char* resourceUseName(ResourceUse use);

// What a pass tells the graph in FramePass::setup: the frame's textures it reads and writes, by name
// (FrameResources.hpp names the built-in ones). A pass may touch only what it declared.
class FramePassBuilder {
public:
    // The pass reads `resource`; throws rhi::Error for a name the frame does not know (listing those it does).
    void read(std::string_view resource, ResourceUse use = ResourceUse::Sampled);
    // The pass writes `resource`; throws as read() does.
    void write(std::string_view resource, ResourceUse use = ResourceUse::RenderTarget);
    // The pass has effects outside the frame's textures (a readback, a counter): the graph never culls it.
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
