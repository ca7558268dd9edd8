#include "penumbra/shadows/LightSpaceCache.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

const glm::vec3 kCachedSun = glm::normalize(glm::vec3(0.5f, -0.6f, -0.4f));

// Whether the cache's boxes are, bit for bit, those lightSpaceCasters makes of `world` now.
bool sameAsFresh(const LightSpaceCasters& cached, std::span<const Bounds> world)
{
    const LightSpaceCasters fresh = lightSpaceCasters(lightBasis(kCachedSun), world);
    if (cached.light.size() != fresh.light.size() || cached.top != fresh.top || cached.world.data() != world.data())
        return false;
    for (std::size_t i = 0; i < fresh.light.size(); ++i)
        if (cached.light[i].min != fresh.light[i].min || cached.light[i].max != fresh.light[i].max)
            return false;
    return true;
}

// Five unit boxes in a row; box 2 then moves up above the others (the top caster) with the move logged or not.
bool movedBoxMatchesFresh(bool logged)
{
    std::vector<Bounds> world;
    for (int i = 0; i < 5; ++i)
        world.push_back({glm::vec3(float(i), 0.0f, 0.0f), glm::vec3(float(i) + 1.0f, 1.0f, 1.0f)});
    CasterChanges changes;
    changes.advance();
    LightSpaceCache cache;
    EXPECT_TRUE(sameAsFresh(cache.casters(kCachedSun, world, changes), world));
    world[2] = {glm::vec3(2.0f, 10.0f, 0.0f), glm::vec3(3.0f, 11.0f, 1.0f)};
    if (logged)
        changes.changed(2);
    changes.advance();
    return sameAsFresh(cache.casters(kCachedSun, world, changes), world);
}

TEST(LightSpaceCacheTest, MovedCasterIsTransformedAgain) { EXPECT_TRUE(movedBoxMatchesFresh(true)); }

TEST(LightSpaceCacheTest, UnloggedMoveCatchesFault) { EXPECT_FALSE(movedBoxMatchesFresh(false)); }

TEST(LightSpaceCacheTest, AnotherDirectionOrCountIsMadeAnew)
{
    std::vector<Bounds> world(3, Bounds{glm::vec3(0.0f), glm::vec3(1.0f)});
    CasterChanges changes;
    changes.advance();
    LightSpaceCache cache;
    cache.casters(kCachedSun, world, changes);
    const glm::vec3 other = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.3f));
    EXPECT_EQ(cache.casters(other, world, changes).basis.direction, lightBasis(other).direction);
    world.push_back({glm::vec3(5.0f), glm::vec3(6.0f)});
    EXPECT_TRUE(sameAsFresh(cache.casters(kCachedSun, world, changes), world)) << "a fourth caster, nothing logged";
}

} // namespace
} // namespace penumbra::shadows
