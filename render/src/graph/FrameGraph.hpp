#pragma once

#include "penumbra/render/FramePass.hpp"
#include "penumbra/rhi/Device.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::render {

// A frame's passes, textures and buffers (Filament's FrameGraph; O'Donnell, "FrameGraph: Extensible Rendering
// Architecture in Frostbite", GDC 2017). Each frame: reset(), import and create textures, import the buffers that
// passes write and others read within the frame, add passes in running order, compile()
// (setup, checks, culling, transient textures), execute() into a command list; after its submission, timings().
// Textures made for the frame live in the graph's pool across frames, so a frame like the last makes none.
class FrameGraph {
public:
    explicit FrameGraph(rhi::Device& device);
    ~FrameGraph();
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;

    void reset();
    // A texture made outside the graph. The frame exists to write its outputs: a pass none of whose writes leads to
    // an output (or to a pass that keep()s) is culled.
    void importTexture(std::string_view name, const rhi::Texture& texture, bool output = false);
    // A texture the graph makes for the passes between the first and the last that use it; textures of one
    // description whose spans do not overlap share one (TransientSlots.hpp).
    void createTexture(std::string_view name, const rhi::TextureDesc& desc);
    // Buffers made outside the graph that one pass writes and later ones read, under one name: the uses a pass
    // declares for the name hold for each of them (the vertex buffers skinning poses, read by every pass that draws).
    // An output is read after the frame (by the host, after the submission).
    void importBuffers(std::string_view name, std::vector<const rhi::Buffer*> buffers, bool output = false);
    void importBuffer(std::string_view name, const rhi::Buffer& buffer, bool output = false)
    {
        importBuffers(name, {&buffer}, output);
    }
    // In running order; the pass must outlive execute(). Throws rhi::Error for a second pass of one name.
    void addPass(FramePass& pass);

    // Runs every pass's setup (which throws rhi::Error for a texture the frame does not have), then throws rhi::Error
    // for a pass that reads a made texture before any pass writes it; culls, and makes the transient textures.
    void compile();
    // Records the passes that run, each in a debug label of its name and between timestamps where the device has them,
    // each after the barriers its declared uses need (CommandList::resourceBarriers, inside its label, so that the RHI
    // holds the pass to them: a texture or buffer of the frame it touches without declaring it is an rhi::Error naming
    // both).
    void execute(rhi::CommandList& commands);
    // After the submission of execute()'s commands: every pass that ran, in order.
    std::vector<PassTiming> timings();
    // The compiled frame as Graphviz dot: passes in order (culled ones dashed, ones off this frame dotted), textures
    // as ellipses and buffers as cylinders (outputs double-bordered, transient textures filled), an arrow per declared
    // use (uses other than sampled and render target named).
    std::string dot() const;

    // Framebuffers reference their textures: call when an imported texture is made anew.
    void dropFramebuffers() { framebuffers_.clear(); }

private:
    friend class FramePassBuilder;
    friend class FramePassContext;

    struct Use {
        std::size_t resource;
        ResourceUse use;
    };
    struct Pass {
        FramePass* pass;
        std::string name;
        bool runs = false; // setup() said so
        bool culled = false;
        std::vector<Use> uses;
        bool kept = false;
    };
    struct Resource {
        std::string name;
        const rhi::Texture* texture = nullptr; // imported, or the pool's once compiled
        std::optional<rhi::TextureDesc> transient;
        bool output = false;
        bool isBuffer = false;
        std::vector<const rhi::Buffer*> buffers; // a buffer resource's (none where the frame has none of them)
    };

    std::size_t resourceIndex(std::string_view name) const;
    void addResource(Resource resource);
    void declare(std::size_t pass, std::string_view resource, ResourceUse use);
    void checkOrder() const;
    void cull();
    void makeTransients();
    // The declared resource of that name; throws rhi::Error where the pass did not declare it or it is not a buffer
    // (a texture).
    const Resource& declared(std::size_t pass, std::string_view resource, bool buffer) const;
    // The barriers before each pass of timed_ (passBarriers): its uses as RHI states, merged per texture and buffer
    // (transient textures may share one), each moving from the state the frame's earlier passes left it in.
    std::vector<std::vector<rhi::ResourceBarrier>> timedBarriers() const;
    const rhi::Framebuffer& framebuffer(std::size_t pass, std::initializer_list<std::string_view> colors,
                                        std::string_view depth);

    rhi::Device& device_;
    std::vector<Pass> passes_;
    std::vector<Resource> resources_;
    // The pool: per texture description (TextureKey), its slots' textures.
    std::map<std::string, std::vector<std::unique_ptr<rhi::Texture>>> pool_;
    std::map<std::vector<const rhi::Texture*>, std::unique_ptr<rhi::Framebuffer>> framebuffers_;
    std::unique_ptr<rhi::TimestampQueries> timestamps_;
    std::vector<std::size_t> timed_; // the passes execute() recorded, in order
};

} // namespace penumbra::render
