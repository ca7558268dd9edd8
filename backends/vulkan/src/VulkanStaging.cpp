#include "VulkanStaging.hpp"

#include "penumbra/rhi/HugePages.hpp"

namespace penumbra::vulkan {

MappedBuffer& StagingBuffer::reserve(VkDeviceSize size)
{
    if (!buffer_ || size_ < size) {
        buffer_.reset();
        buffer_.emplace(context_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        size_ = size;
        rhi::adviseHugePages(buffer_->data(), size);
    }
    return *buffer_;
}

} // namespace penumbra::vulkan
