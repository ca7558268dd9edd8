#pragma once

#include "DrawScene.hpp"

#include <memory>

namespace penumbra::apps {

// The benchmark's reference: the same frame as DrawScene::recordRhi, written by hand on the
// raw API over the scene's native objects (pipeline, buffers, framebuffer), and waited for.
class RawDraws {
public:
    virtual ~RawDraws() = default;
    virtual void frame() = 0;
};

std::unique_ptr<RawDraws> createRawVulkanDraws(rhi::Device& device, const DrawScene& scene);
std::unique_ptr<RawDraws> createRawOpenGLDraws(rhi::Device& device, const DrawScene& scene);

// The raw reference of the device's backend (DeviceDesc::backend); one without one throws rhi::UnsupportedError.
std::unique_ptr<RawDraws> createRawDraws(rhi::Device& device, const DrawScene& scene);

} // namespace penumbra::apps
