#pragma once

#include "VulkanResources.hpp"

#include <functional>
#include <memory>
#include <optional>

namespace penumbra::vulkan {

// The host-visible buffer that texture uploads copy through, kept from one upload to the next and grown to the
// largest so far. A fresh staging buffer per upload touched fresh memory every time: with a dozen 2048 x 2048 textures
// (12 levels each) that was 256 MiB of page faults on lavapipe, where buffers are process memory, for 16 MiB of
// staging (docs/notes/2026-12-07-loading-time.md). Used on the device's thread only, as writeTexture is.
class StagingBuffer {
public:
    // The most it keeps: a 4096 x 4096 RGBA8 level. A larger upload gets a buffer of its own, released after it, so
    // one huge texture does not hold its size in staging for the device's life.
    static constexpr VkDeviceSize kKeptBytes = VkDeviceSize(64) << 20;

    explicit StagingBuffer(std::shared_ptr<Context> context) : context_(std::move(context)) {}

    // Calls `copy` with a staging buffer of at least `size` bytes (what it held before is gone).
    void use(VkDeviceSize size, const std::function<void(MappedBuffer&)>& copy);

private:
    std::shared_ptr<Context> context_;
    std::optional<MappedBuffer> kept_;
    VkDeviceSize keptSize_ = 0;
};

} // namespace penumbra::vulkan
