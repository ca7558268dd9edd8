#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace penumbra::rhi {

// Every RHI object kind: each interface class (Device, Buffer, Texture, ...) derives from LiveObject<kind>,
// so the live count of each kind is kept in this one place, whatever the backend. `penumbra soak` reads them to
// find objects that are created and never destroyed.
enum class ObjectKind : std::uint8_t {
    Device,
    Buffer,
    Texture,
    Sampler,
    Framebuffer,
    Shader,
    Pipeline,
    CommandList,
    TimestampQueries,
    Swapchain,
    BindingSet, // binding sets and their layouts
};
inline constexpr std::size_t kObjectKindCount = 11;

// "device", "buffer", "texture", ... (as the soak's report names them).
std::string_view objectKindName(ObjectKind kind);

// Objects alive in this process now, per kind (indexed by ObjectKind), over every device.
using LiveObjectCounts = std::array<std::int64_t, kObjectKindCount>;
LiveObjectCounts liveObjectCounts();

namespace detail {
void countLiveObject(ObjectKind kind, int change) noexcept;
} // namespace detail

// Counts itself in at construction (copies too) and out at destruction.
template <ObjectKind Kind>
class LiveObject {
protected:
    LiveObject() noexcept { detail::countLiveObject(Kind, +1); }
    // A copy is one more live object of its kind.
    LiveObject(const LiveObject&) noexcept { detail::countLiveObject(Kind, +1); }
    // Assignment changes no count.
    LiveObject& operator=(const LiveObject&) noexcept = default;
    ~LiveObject() { detail::countLiveObject(Kind, -1); }
};

} // namespace penumbra::rhi
