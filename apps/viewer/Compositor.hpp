#pragma once

#include "penumbra/rhi/Device.hpp"

#include <functional>
#include <memory>

namespace penumbra::viewer {

// The picture the window shows: the scene's image drawn over the whole target with
// fullscreen.vert, then the UI on top. It lives in an ordinary RHI texture (row 0 at the top),
// which the swapchain presents the right way up on every backend.
class Compositor {
public:
    static constexpr rhi::Format kFormat = rhi::Format::RGBA8;

    explicit Compositor(rhi::Device& device);

    // Draws and submits one frame at `size` (resizing on demand); `drawOnTop` records more draws
    // (the UI) into the open pass.
    void compose(const rhi::Texture& scene, rhi::Extent size,
                 const std::function<void(rhi::CommandList&)>& drawOnTop = {});

    const rhi::Texture& image() const { return *image_; }

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_;
    std::unique_ptr<rhi::Shader> fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::CommandList> commands_;
    std::unique_ptr<rhi::Texture> image_;
    std::unique_ptr<rhi::Framebuffer> target_;
};

} // namespace penumbra::viewer
