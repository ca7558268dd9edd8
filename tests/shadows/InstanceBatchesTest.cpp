#include "penumbra/shadows/InstanceBatches.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

using Batch = InstanceBatches::Batch;

// The group of item i is groups[i].
auto groupIn(const std::vector<std::uint32_t>& groups)
{
    return [&groups](std::uint32_t item) { return groups[item]; };
}

TEST(InstanceBatchesTest, GroupsJoinInTheOrderOfTheirFirstItem)
{
    const std::vector<std::uint32_t> groups{7, 2, 7, 2, 0, 7};
    const std::vector<std::uint32_t> items{0, 1, 2, 3, 4, 5};
    const InstanceBatches b = batchByGroup(std::span(items), groupIn(groups));
    EXPECT_EQ(b.items, (std::vector<std::uint32_t>{0, 2, 5, 1, 3, 4}));
    EXPECT_EQ(b.batches, (std::vector<Batch>{{0, 3}, {3, 2}, {5, 1}}));
}

TEST(InstanceBatchesTest, ItemsWithoutAGroupAreDrawnAlone)
{
    const std::vector<std::uint32_t> groups{kNoDrawGroup, 1, kNoDrawGroup, 1};
    const std::vector<std::uint32_t> items{3, 2, 1, 0};
    const InstanceBatches b = batchByGroup(std::span(items), groupIn(groups));
    EXPECT_EQ(b.items, (std::vector<std::uint32_t>{3, 1, 2, 0}));
    EXPECT_EQ(b.batches, (std::vector<Batch>{{0, 2}, {2, 1}, {3, 1}}));
}

TEST(InstanceBatchesTest, OnlyTheGivenItemsAreBatched)
{
    const std::vector<std::uint32_t> groups{0, 0, 0, 0, 0};
    const std::vector<std::uint32_t> culled{1, 4};
    const InstanceBatches b = batchByGroup(std::span(culled), groupIn(groups));
    EXPECT_EQ(b.items, culled);
    EXPECT_EQ(b.batches, (std::vector<Batch>{{0, 2}}));
    EXPECT_TRUE(batchByGroup(std::span<const std::uint32_t>(), groupIn(groups)).batches.empty());
}

TEST(InstanceBatchesTest, RunsKeepTheOrder)
{
    const std::vector<std::uint32_t> groups{4, 4, 5, 4, kNoDrawGroup, kNoDrawGroup};
    const std::vector<std::uint32_t> items{0, 1, 2, 3, 4, 5};
    const InstanceBatches b = batchRuns(std::span(items), groupIn(groups));
    EXPECT_EQ(b.items, items);
    EXPECT_EQ(b.batches, (std::vector<Batch>{{0, 2}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}));
}

TEST(InstanceTransformTest, RowsAreTheModelsFirstThreeRows)
{
    const glm::mat4 model =
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), 0.7f, glm::vec3(0, 1, 0)),
                   glm::vec3(2.0f, -1.0f, 0.5f));
    const InstanceTransform t = instanceTransform(model);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_EQ(t.rows[r][c], model[c][r]) << r << ", " << c;
    EXPECT_EQ(InstanceTransform{}.rows, instanceTransform(glm::mat4(1.0f)).rows);
}

} // namespace
} // namespace penumbra::shadows
