#pragma once

#include "VulkanResources.hpp"

#include <memory>
#include <optional>

namespace penumbra::vulkan {

// The host-visible buffer that texture uploads copy through, kept from one upload to the next and grown to the
// largest so far. A fresh staging buffer per upload touched fresh memory every time: with a dozen 2048 x 2048 textures
// (13 levels each) that was 256 MiB of page faults on lavapipe, where buffers are process memory, for 16 MiB of
// staging (docs/notes/2026-12-07-loading-time.md). Used on the device's thread only, as writeTexture is.
class StagingBuffer {
public:
    explicit StagingBuffer(std::shared_ptr<Context> context) : context_(std::move(context)) {}

    // The buffer, at least `size` bytes; what it held before is gone.
    MappedBuffer& reserve(VkDeviceSize size);

private:
    std::shared_ptr<Context> context_;
    std::optional<MappedBuffer> buffer_;
    VkDeviceSize size_ = 0;
};

} // namespace penumbra::vulkan
