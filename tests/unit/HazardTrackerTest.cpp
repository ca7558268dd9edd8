// The hazard tracker's decisions on the CPU (rhi/Hazards.hpp): which barrier each use needs, and that a hazard once
// ordered is not ordered again.
#include "penumbra/rhi/Hazards.hpp"

#include <gtest/gtest.h>

namespace penumbra::rhi {
namespace {

const Use computeWrite{Stage::ComputeShader, Access::StorageBufferRead | Access::StorageBufferWrite};
const Use computeRead{Stage::ComputeShader, Access::StorageBufferRead};

bool operator==(const Use& a, const Use& b) { return a.stages == b.stages && a.access == b.access; }

TEST(HazardTrackerTest, AResultIsOrderedBeforeTheStagesItsUsagesAllowOnce)
{
    HazardTracker tracker;
    const int buffer = 0;
    const Use graphics = graphicsUses(BufferDesc{.usage = BufferUsage::Vertex | BufferUsage::Indirect});
    EXPECT_TRUE(graphics == (Use{Stage::VertexInput | Stage::DrawIndirect, Access::VertexRead | Access::IndirectRead}));
    Barrier first;
    tracker.use(&buffer, graphics, computeWrite, first);
    EXPECT_TRUE(first.empty()); // nothing came before
    const Barrier pass = tracker.beginPass();
    EXPECT_TRUE(pass.src == (Use{Stage::ComputeShader, Access::StorageBufferWrite}));
    EXPECT_TRUE(pass.dst == graphics);
    EXPECT_TRUE(tracker.beginPass().empty()); // already ordered
}

TEST(HazardTrackerTest, DispatchesAreOrderedAmongThemselves)
{
    HazardTracker tracker;
    const int buffer = 0;
    const Use graphics = graphicsUses(BufferDesc{.usage = BufferUsage::Storage});
    Barrier barrier;
    tracker.use(&buffer, graphics, computeWrite, barrier);
    tracker.use(&buffer, graphics, computeRead, barrier); // read after write
    EXPECT_TRUE(barrier.src == (Use{Stage::ComputeShader, Access::StorageBufferWrite}));
    EXPECT_TRUE(barrier.dst == computeRead);
    Barrier again;
    tracker.use(&buffer, graphics, computeRead, again); // visible already
    EXPECT_TRUE(again.empty());
    Barrier overwrite;
    tracker.use(&buffer, graphics, computeWrite, overwrite); // write after read and write
    EXPECT_FALSE(overwrite.empty());
}

TEST(HazardTrackerTest, ARenderTargetIsOrderedBeforeADispatchAfterAPass)
{
    HazardTracker tracker;
    const int texture = 0;
    const Use graphics = graphicsUses(TextureDesc{.usage = TextureUsage::RenderTarget | TextureUsage::Sampled});
    const Use sampled{Stage::ComputeShader, Access::SampledRead};
    Barrier before;
    tracker.use(&texture, graphics, sampled, before);
    EXPECT_TRUE(before.empty()); // no pass yet
    const Barrier pass = tracker.beginPass(); // the pass may render into what the dispatch read
    EXPECT_TRUE(pass.src == (Use{Stage::ComputeShader, Access::None}));
    EXPECT_TRUE(pass.dst == (Use{Stage::Attachments, Access::AttachmentWrite}));
    Barrier after;
    tracker.use(&texture, graphics, sampled, after);
    EXPECT_TRUE(after.src == (Use{Stage::Attachments, Access::AttachmentWrite}));
    EXPECT_TRUE(after.dst == sampled);
}

TEST(HazardTrackerTest, CopiesAndTheHostSeeADispatchsWrites)
{
    HazardTracker tracker;
    const int buffer = 0;
    const int other = 1;
    Barrier barrier;
    tracker.use(&buffer, {}, computeWrite, barrier);
    EXPECT_TRUE(tracker.copy(&other, {Stage::Copy, Access::CopyRead}).empty()); // never written by a dispatch
    const Barrier copy = tracker.copy(&buffer, {Stage::Copy, Access::CopyRead});
    EXPECT_TRUE(copy.dst == (Use{Stage::Copy, Access::CopyRead}));
    const Barrier host = tracker.finish();
    EXPECT_TRUE(host.dst == (Use{Stage::Host, Access::HostRead}));
    tracker.reset();
    EXPECT_TRUE(tracker.finish().empty());
}

} // namespace
} // namespace penumbra::rhi
