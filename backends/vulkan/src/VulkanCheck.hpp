#pragma once

#include "penumbra/rhi/Error.hpp"

#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" for the results a call can return; the number otherwise.
std::string resultName(VkResult result);

// Throws rhi::Error naming the call ("vkCreateImage") and its result unless it succeeded.
void check(VkResult result, std::string_view call);

// The Vulkan object behind an RHI one; `what` names it if it came from another backend.
// Vk is final, so comparing the dynamic type is exact, and cheaper than dynamic_cast per draw.
template <typename Vk, typename Rhi>
Vk& vulkanObject(Rhi& object, std::string_view what)
{
    static_assert(std::is_final_v<std::remove_const_t<Vk>>);
    if (typeid(object) != typeid(Vk))
        throw rhi::Error(std::string(what) + " was not created by a Vulkan device");
    return static_cast<Vk&>(object);
}

} // namespace penumbra::vulkan
