#include "penumbra/shadows/CasterChanges.hpp"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

using Ranges = std::vector<CasterRange>;

// A log whose first generation built the list (all changed) and whose second moved casters 7, 3, 4 and 7 again.
CasterChanges builtThenMoved()
{
    CasterChanges changes;
    changes.changedAll();
    changes.advance();
    for (const std::uint32_t caster : {7u, 3u, 4u, 7u})
        changes.changed(caster);
    changes.advance();
    return changes;
}

TEST(CasterChangesTest, ChangedCastersSinceAGenerationAreMergedRanges)
{
    const CasterChanges changes = builtThenMoved();
    EXPECT_EQ(changes.generation(), 2u);
    EXPECT_EQ(changes.since(1), (Ranges{{3, 2}, {7, 1}}));
    EXPECT_EQ(changes.since(2), Ranges{}) << "nothing changed since the latest generation";
    EXPECT_EQ(changes.since(0), std::nullopt) << "generation 1 rebuilt the list";
    EXPECT_EQ(changes.since(std::nullopt), std::nullopt) << "a consumer that read nothing reads all";
}

TEST(CasterChangesTest, ChangesOfSeveralGenerationsAreJoined)
{
    CasterChanges changes = builtThenMoved();
    changes.changed(5);
    changes.changed(9);
    changes.advance();
    EXPECT_EQ(changes.since(1), (Ranges{{3, 3}, {7, 1}, {9, 1}}));
    EXPECT_EQ(changes.since(2), (Ranges{{5, 1}, {9, 1}}));
}

TEST(CasterChangesTest, RebuiltOrForgottenGenerationsAskForEverything)
{
    CasterChanges changes = builtThenMoved();
    changes.changedAll();
    changes.changed(2);
    changes.advance();
    EXPECT_EQ(changes.since(2), std::nullopt) << "the list was rebuilt after generation 2";
    EXPECT_EQ(changes.since(3), Ranges{});
    // Generations 4 to 12: the changes of 5 to 12 are kept, those of 4 are not.
    for (std::size_t i = 0; i <= CasterChanges::kKeptGenerations; ++i) {
        changes.changed(1);
        changes.advance();
    }
    EXPECT_EQ(changes.since(4), (Ranges{{1, 1}}));
    EXPECT_EQ(changes.since(3), std::nullopt) << "generation 4 is no longer kept";
    EXPECT_EQ(changes.since(changes.generation() - 1), (Ranges{{1, 1}}));
    EXPECT_EQ(changes.since(changes.generation() + 1), std::nullopt) << "a generation this log never had";
}

} // namespace
} // namespace penumbra::shadows
