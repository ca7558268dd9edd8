#pragma once

#include "penumbra/rhi/Device.hpp"

#include <array>
#include <cstdint>
#include <memory>

namespace penumbra::apps {

// The dispatch benchmark's work: `count` dispatches of one workgroup per frame, each adding one to the same counters
// of a storage buffer. Each dispatch reads what the one before it wrote, so each needs a barrier after the one before:
// the RHI derives it from the bindings, the raw-API paths write it by hand.
class DispatchScene {
public:
    static constexpr std::uint32_t countersBinding = 0;
    // The shader's storage block Counters: one count per invocation of the workgroup.
    struct Counters {
        std::array<std::uint32_t, 64> counts{};
    };

    DispatchScene(rhi::Device& device, std::uint32_t count);

    // One frame through the RHI: bindComputePipeline and bindStorageBuffer once, then `count` dispatches.
    void recordRhi(rhi::CommandList& commands) const;

    std::uint32_t count() const { return count_; }
    const rhi::ComputePipeline& pipeline() const { return *pipeline_; }
    const rhi::Buffer& counters() const { return *counters_; }

private:
    std::uint32_t count_;
    std::unique_ptr<rhi::ComputePipeline> pipeline_;
    std::unique_ptr<rhi::Buffer> counters_;
};

} // namespace penumbra::apps
