#include "VulkanStaging.hpp"

#include "penumbra/rhi/HugePages.hpp"

namespace penumbra::vulkan {

void StagingBuffer::use(VkDeviceSize size, const std::function<void(MappedBuffer&)>& copy)
{
    if (size > kKeptBytes) {
        MappedBuffer once(context_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        rhi::adviseHugePages(once.data(), size);
        copy(once);
        return;
    }
    if (!kept_ || keptSize_ < size) {
        kept_.emplace(context_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        keptSize_ = size;
        rhi::adviseHugePages(kept_->data(), size);
    }
    copy(*kept_);
}

} // namespace penumbra::vulkan
