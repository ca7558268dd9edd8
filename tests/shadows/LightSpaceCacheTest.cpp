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
    if (cached.chunks.size() != fresh.chunks.size())
        return false;
    for (std::size_t k = 0; k < fresh.chunks.size(); ++k)
        if (cached.chunks[k].min != fresh.chunks[k].min || cached.chunks[k].max != fresh.chunks[k].max)
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

// The fits' near depth through the chunks is the least depth of every box over the square, read box by box: squares
// over whole chunks, over parts of some, over one box's edge and over none, on 300 boxes in rows (5 chunks).
TEST(LightSpaceCacheTest, NearestDepthIsTheBruteForceOne)
{
    std::vector<Bounds> world;
    for (int i = 0; i < 300; ++i) {
        const glm::vec3 at(float(i % 20), float((i * 7) % 5), float(i / 20));
        world.push_back({at, at + glm::vec3(0.5f)});
    }
    const LightSpaceCasters casters = lightSpaceCasters(lightBasis(glm::vec3(0.0f, 0.0f, -1.0f)), world);
    ASSERT_EQ(casters.chunks.size(), 5u);
    for (const glm::vec3 square : {glm::vec3(10.0f, 10.0f, 30.0f), glm::vec3(3.0f, 2.0f, 2.0f),
                                   glm::vec3(-5.5f, 0.0f, 0.5f), glm::vec3(100.0f, 0.0f, 1.0f)}) {
        const glm::vec2 centre(square);
        const float half = square.z;
        float brute = 1e9f;
        for (const Bounds& b : casters.light)
            if (b.max.x >= centre.x - half && b.min.x <= centre.x + half && b.max.y >= centre.y - half &&
                b.min.y <= centre.y + half)
                brute = std::min(brute, b.min.z);
        EXPECT_EQ(nearestDepthOver(casters, centre, half, 1e9f), brute) << square.x << " " << square.y << " " << half;
    }
}

} // namespace
} // namespace penumbra::shadows
