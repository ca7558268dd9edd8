// Negative controls of the barriers the RHI derives (rhi/Hazards.hpp): each scene of ComputeScenes runs with the
// list's barriers suppressed, and Vulkan's synchronization validation must report the hazard at the command that
// reads too early. GL has no such layer, and lavapipe forgives the missing barrier in the results; so these run on
// Vulkan only, and name the hazard and the command they expect.
#include "ComputeScenes.hpp"
#include "GpuTesting.hpp"

#include <algorithm>

namespace penumbra::testing {
namespace {

class HazardTest : public GpuTest {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        if (device->desc().backend != "vulkan")
            GTEST_SKIP() << "synchronization validation is Vulkan's";
    }

    // The messages since the last call that report `hazard` at `command`; forgets every message.
    std::vector<std::string> reports(std::string_view hazard, std::string_view command)
    {
        std::vector<std::string> found;
        for (const std::string& m : device->debugMessages())
            if (m.find(hazard) != std::string::npos && m.find(command) != std::string::npos)
                found.push_back(m);
        device->clearDebugMessages();
        return found;
    }
};

const SceneOptions suppressed{.suppressBarriers = true};

TEST_F(HazardTest, ComputeWriteThenIndirectDrawCatchesFault)
{
    computedTriangle(*device, true, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDrawIndirect").empty());
}

TEST_F(HazardTest, ComputeWriteThenVertexReadCatchesFault)
{
    computedTriangle(*device, false, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDraw").empty());
}

TEST_F(HazardTest, RenderTargetThenComputeReadCatchesFault)
{
    pictureHistogram(*device, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDispatch").empty());
}

TEST_F(HazardTest, ComputeWriteThenCopyCatchesFault)
{
    prefixSum(*device, {1, 2, 3}, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdCopyBuffer").empty());
}

TEST_F(HazardTest, ComputeWriteThenDispatchIndirectCatchesFault)
{
    indirectInvocations(*device, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDispatchIndirect").empty());
}

TEST_F(HazardTest, ComputeWriteThenComputeReadCatchesFault)
{
    storageImageSum(*device, suppressed);
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDispatch").empty());
}

// The tracker sees what a binding set binds as it sees single binds, also when the pipelines list the set's layout
// (on Vulkan, the set's own descriptor set).
TEST_F(HazardTest, ComputeWriteThenComputeReadThroughABindingSetCatchesFault)
{
    storageImageSum(*device, {.suppressBarriers = true, .bindingSet = true});
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDispatch").empty());
    storageImageSum(*device, {.suppressBarriers = true, .bindingSet = true, .listedLayout = true});
    EXPECT_FALSE(reports("SYNC-HAZARD-READ-AFTER-WRITE", "vkCmdDispatch").empty());
}

} // namespace
} // namespace penumbra::testing
