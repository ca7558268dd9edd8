#pragma once

#include "DispatchScene.hpp"
#include "DrawScene.hpp"

#include <memory>

namespace penumbra::apps {

// A benchmark's reference: the same frame as a scene's recordRhi, written by hand on the raw API over the scene's
// native objects (pipeline, buffers, framebuffer), and waited for.
class RawFrame {
public:
    virtual ~RawFrame() = default;
    virtual void frame() = 0;
};

std::unique_ptr<RawFrame> createRawVulkanDraws(rhi::Device& device, const DrawScene& scene, DrawCall call);
std::unique_ptr<RawFrame> createRawOpenGLDraws(rhi::Device& device, const DrawScene& scene, DrawCall call);
std::unique_ptr<RawFrame> createRawVulkanDispatches(rhi::Device& device, const DispatchScene& scene);
std::unique_ptr<RawFrame> createRawOpenGLDispatches(rhi::Device& device, const DispatchScene& scene);

// The raw reference of the device's backend (DeviceDesc::backend); one without one throws rhi::UnsupportedError.
std::unique_ptr<RawFrame> createRawDraws(rhi::Device& device, const DrawScene& scene, DrawCall call);
std::unique_ptr<RawFrame> createRawDispatches(rhi::Device& device, const DispatchScene& scene);

} // namespace penumbra::apps
