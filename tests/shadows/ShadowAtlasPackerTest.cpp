// The local atlas's mixed-size tile packer: no overlap, stable tiles, degradation order, the report.
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowAtlasPacker.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

namespace penumbra::shadows {
namespace {

// Every tile of every light lies inside the atlas, on its own size's grid, and no two tiles share a texel.
void expectDisjointPackedTiles(const ShadowAtlasPack& pack, std::uint32_t atlasSize)
{
    struct Tile {
        glm::uvec2 offset;
        std::uint32_t size;
    };
    std::vector<Tile> tiles;
    for (const PackedLight& light : pack.lights)
        for (const glm::uvec2 offset : light.offsets) {
            EXPECT_EQ(offset.x % light.size, 0u);
            EXPECT_EQ(offset.y % light.size, 0u);
            EXPECT_LE(offset.x + light.size, atlasSize);
            EXPECT_LE(offset.y + light.size, atlasSize);
            tiles.push_back({offset, light.size});
        }
    for (std::size_t a = 0; a < tiles.size(); ++a)
        for (std::size_t b = a + 1; b < tiles.size(); ++b) {
            const bool apart = tiles[a].offset.x + tiles[a].size <= tiles[b].offset.x ||
                               tiles[b].offset.x + tiles[b].size <= tiles[a].offset.x ||
                               tiles[a].offset.y + tiles[a].size <= tiles[b].offset.y ||
                               tiles[b].offset.y + tiles[b].size <= tiles[a].offset.y;
            EXPECT_TRUE(apart) << "tiles " << a << " and " << b << " overlap";
        }
}

const PackedLight& lightOf(const ShadowAtlasPack& pack, std::uint32_t id)
{
    for (const PackedLight& light : pack.lights)
        if (light.lightId == id)
            return light;
    throw std::runtime_error("no such light");
}

TEST(ShadowAtlasPacker, RoundsAndClampsRequestsToPowersOfTwo)
{
    ShadowAtlasPacker packer({.atlasSize = 4096, .floorSize = 64, .maxSize = 1024});
    const std::vector<ShadowTileRequest> requests{{.lightId = 1, .size = 300.0f},
                                                  {.lightId = 2, .size = 363.0f}, // above 256 x sqrt 2
                                                  {.lightId = 3, .size = 5.0f},
                                                  {.lightId = 4, .size = 9000.0f}};
    const ShadowAtlasPack pack = packer.pack(requests);
    EXPECT_EQ(pack.lights[0].size, 256u);
    EXPECT_EQ(pack.lights[1].size, 512u);
    EXPECT_EQ(pack.lights[2].size, 64u);
    EXPECT_EQ(pack.lights[3].size, 1024u);
    EXPECT_TRUE(pack.notes.empty());
    EXPECT_FALSE(pack.repacked);
    EXPECT_EQ(pack.usedTexels, 256u * 256 + 512 * 512 + 64 * 64 + 1024 * 1024);
    EXPECT_EQ(pack.usedTexels + pack.freeTexels, 4096u * 4096);
    expectDisjointPackedTiles(pack, 4096);
}

TEST(ShadowAtlasPacker, RandomFramesNeverOverlapAndAccountForEveryTexel)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> size(16.0f, 3000.0f);
    std::uniform_real_distribution<float> priority(0.0f, 1.0f);
    std::uniform_int_distribution<std::uint32_t> id(0, 200);
    ShadowAtlasPacker packer({.atlasSize = 4096, .floorSize = 64, .maxSize = 2048});
    for (int frame = 0; frame < 30; ++frame) {
        std::vector<ShadowTileRequest> requests;
        std::vector<bool> taken(201, false);
        for (int i = 0; i < 60; ++i) {
            const std::uint32_t light = id(rng);
            if (taken[light])
                continue;
            taken[light] = true;
            requests.push_back({light, size(rng), priority(rng), light % 5 == 0 ? 6u : 1u});
        }
        const ShadowAtlasPack pack = packer.pack(requests);
        expectDisjointPackedTiles(pack, 4096);
        EXPECT_EQ(pack.usedTexels + pack.freeTexels, 4096u * 4096) << frame;
        for (const PackedLight& light : pack.lights)
            EXPECT_EQ(light.offsets.size(), light.size == 0 ? 0u : (light.lightId % 5 == 0 ? 6u : 1u));
    }
}

TEST(ShadowAtlasPacker, TilesStayPutWhileRequestsMoveWithinTheHysteresis)
{
    ShadowAtlasPacker packer({.atlasSize = 2048, .floorSize = 64, .maxSize = 1024, .hysteresis = 0.25f});
    std::vector<ShadowTileRequest> requests;
    for (std::uint32_t i = 0; i < 12; ++i)
        requests.push_back({i, 64.0f * static_cast<float>(1 + i % 8), static_cast<float>(i), i == 3 ? 6u : 1u});
    const ShadowAtlasPack first = packer.pack(requests);
    // Every request changes by up to 60% (0.68 octave of a tile's 0.75 band); priorities change order too.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> factor(1.0f / 1.6f, 1.6f);
    for (int frame = 0; frame < 20; ++frame) {
        std::vector<ShadowTileRequest> moved = requests;
        for (ShadowTileRequest& r : moved) {
            r.size = static_cast<float>(lightOf(first, r.lightId).wantedSize) * factor(rng);
            r.priority = factor(rng);
        }
        const ShadowAtlasPack next = packer.pack(moved);
        for (const PackedLight& light : next.lights) {
            const PackedLight& before = lightOf(first, light.lightId);
            EXPECT_EQ(light.size, before.size) << light.lightId;
            EXPECT_EQ(light.offsets, before.offsets) << light.lightId;
            EXPECT_FALSE(light.moved) << light.lightId;
        }
    }
    // Beyond the band the size changes, and only that light's tile moves.
    std::vector<ShadowTileRequest> grown = requests;
    grown[5].size = static_cast<float>(lightOf(first, 5).wantedSize) * 1.7f;
    const ShadowAtlasPack next = packer.pack(grown);
    EXPECT_EQ(next.lights[5].size, 2 * first.lights[5].size);
    EXPECT_TRUE(next.lights[5].moved);
    for (std::size_t i = 0; i < next.lights.size(); ++i)
        EXPECT_EQ(next.lights[i].moved, i == 5) << i;
    expectDisjointPackedTiles(next, 2048);
}

TEST(ShadowAtlasPacker, LightsComingAndGoingLeaveTheOthersInPlace)
{
    ShadowAtlasPacker packer({.atlasSize = 1024, .floorSize = 32, .maxSize = 512});
    std::vector<ShadowTileRequest> requests;
    for (std::uint32_t i = 0; i < 10; ++i)
        requests.push_back({i, 128.0f, 1.0f});
    const ShadowAtlasPack first = packer.pack(requests);
    std::vector<ShadowTileRequest> changed(requests.begin() + 2, requests.end()); // lights 0 and 1 leave
    changed.push_back({100, 256.0f, 5.0f});
    changed.push_back({101, 64.0f, 0.0f});
    const ShadowAtlasPack next = packer.pack(changed);
    for (std::uint32_t i = 2; i < 10; ++i) {
        EXPECT_EQ(lightOf(next, i).offsets, lightOf(first, i).offsets);
        EXPECT_FALSE(lightOf(next, i).moved);
    }
    EXPECT_TRUE(lightOf(next, 100).moved);
    EXPECT_EQ(lightOf(next, 100).size, 256u);
    expectDisjointPackedTiles(next, 1024);
}

TEST(ShadowAtlasPacker, SpaceRunsOutLargestTilesHalveFirstOfEqualOnesTheLowestPriority)
{
    // 1024^2 holds four 512 tiles; five lights ask for 512.
    ShadowAtlasPacker packer({.atlasSize = 1024, .floorSize = 64, .maxSize = 512});
    std::vector<ShadowTileRequest> requests;
    for (std::uint32_t i = 0; i < 5; ++i)
        requests.push_back({i, 512.0f, static_cast<float>(10 - i)}); // light 4 has the lowest priority
    const ShadowAtlasPack pack = packer.pack(requests);
    // Area 5 x 512^2 exceeds 4 x 512^2: light 4 halves (4 x 512^2 + 256^2 still exceeds it), then light 3, the lowest
    // priority of the four largest.
    EXPECT_EQ(pack.lights[4].size, 256u);
    EXPECT_EQ(pack.lights[3].size, 256u);
    for (std::uint32_t i = 0; i < 3; ++i)
        EXPECT_EQ(pack.lights[i].size, 512u) << i;
    ASSERT_EQ(pack.notes.size(), 2u);
    EXPECT_EQ(pack.notes[0].lightId, 3u);
    EXPECT_EQ(pack.notes[0].reason, "shadow tile 256 x 256 instead of 512 x 512: the tiles asked for need 125% of "
                                    "the 1024 x 1024 local atlas; larger tiles, then lower priorities, are lowered "
                                    "first");
    EXPECT_EQ(pack.notes[1].lightId, 4u);
    expectDisjointPackedTiles(pack, 1024);

    // A light of higher priority that asks for more gives up resolution before a smaller one goes to the floor.
    const ShadowAtlasPack uneven = ShadowAtlasPacker({.atlasSize = 512, .floorSize = 64, .maxSize = 512})
                                       .pack(std::vector<ShadowTileRequest>{{1, 512.0f, 9.0f}, {2, 256.0f, 1.0f}});
    EXPECT_EQ(uneven.lights[0].size, 256u);
    EXPECT_EQ(uneven.lights[1].size, 256u);
    expectDisjointPackedTiles(uneven, 512);
}

TEST(ShadowAtlasPacker, ALightLosesItsShadowOnlyWhenEveryLightIsAtTheFloor)
{
    // 256^2 holds sixteen 64 tiles: a point light (six faces) and twelve spot lights at the floor need eighteen.
    ShadowAtlasPacker packer({.atlasSize = 256, .floorSize = 64, .maxSize = 256});
    std::vector<ShadowTileRequest> requests{{.lightId = 50, .size = 256.0f, .priority = 9.0f, .tileCount = 6}};
    for (std::uint32_t i = 0; i < 12; ++i)
        requests.push_back({i, 128.0f, static_cast<float>(i)});
    const ShadowAtlasPack pack = packer.pack(requests);
    EXPECT_EQ(pack.lights[0].size, 64u);
    EXPECT_EQ(pack.lights[0].offsets.size(), 6u);
    // Lights 0 and 1, the lowest priorities, lose their shadows; the others keep floor tiles.
    EXPECT_EQ(pack.lights[1].size, 0u);
    EXPECT_TRUE(pack.lights[1].offsets.empty());
    EXPECT_EQ(pack.lights[2].size, 0u);
    for (std::size_t i = 3; i < pack.lights.size(); ++i)
        EXPECT_EQ(pack.lights[i].size, 64u) << i;
    EXPECT_EQ(pack.freeTexels, 0u);
    EXPECT_EQ(pack.largestFreeTile, 0u);
    const auto note =
        std::find_if(pack.notes.begin(), pack.notes.end(), [](const ShadowAtlasPackNote& n) { return n.lightId == 0; });
    ASSERT_NE(note, pack.notes.end());
    EXPECT_EQ(note->reason, "no shadow: the 256 x 256 local atlas has no room for its 1 tile(s) of the floor size "
                            "64 x 64 with every light of higher priority at that size");
    EXPECT_EQ(pack.notes.size(), 13u); // two without shadows, eleven lowered
}

TEST(ShadowAtlasPacker, ShrinkingLightsKeepTheirCornerAndFreedSpaceIsReused)
{
    ShadowAtlasPacker packer({.atlasSize = 512, .floorSize = 32, .maxSize = 512, .hysteresis = 0.0f});
    const ShadowAtlasPack first = packer.pack(std::vector<ShadowTileRequest>{{1, 256.0f, 1.0f}, {2, 256.0f, 2.0f}});
    const ShadowAtlasPack next = packer.pack(std::vector<ShadowTileRequest>{{1, 64.0f, 1.0f}, {2, 256.0f, 2.0f}});
    EXPECT_EQ(next.lights[0].size, 64u);
    EXPECT_EQ(next.lights[0].offsets, first.lights[0].offsets);
    EXPECT_TRUE(next.lights[0].moved);
    EXPECT_FALSE(next.lights[1].moved);
    // Free: two 256 squares, three 128 and three 64 (the rest of light 1's old tile): 1 - 256^2 / free.
    EXPECT_EQ(next.freeTexels, 512u * 512 - 256 * 256 - 64 * 64);
    EXPECT_EQ(next.largestFreeTile, 256u);
    EXPECT_NEAR(next.fragmentation, 1.0f - 65536.0f / static_cast<float>(next.freeTexels), 1e-6f);
}

TEST(ShadowAtlasPacker, ALightWhoseTileCountChangesIsPlacedAgain)
{
    ShadowAtlasPacker packer({.atlasSize = 1024, .floorSize = 64, .maxSize = 256});
    packer.pack(std::vector<ShadowTileRequest>{{1, 256.0f, 1.0f, 6}, {2, 128.0f, 1.0f}});
    const ShadowAtlasPack fewer = packer.pack(std::vector<ShadowTileRequest>{{1, 256.0f, 1.0f, 1}, {2, 128.0f, 1.0f}});
    EXPECT_EQ(fewer.lights[0].offsets.size(), 1u);
    EXPECT_TRUE(fewer.lights[0].moved);
    EXPECT_FALSE(fewer.lights[1].moved);
    const ShadowAtlasPack shrunk = packer.pack(std::vector<ShadowTileRequest>{{1, 64.0f, 1.0f, 6}, {2, 128.0f, 1.0f}});
    EXPECT_EQ(shrunk.lights[0].offsets.size(), 6u);
    EXPECT_EQ(shrunk.usedTexels + shrunk.freeTexels, 1024u * 1024);
    expectDisjointPackedTiles(shrunk, 1024);
}

TEST(ShadowAtlasPacker, KeptTilesThatLeaveNoRoomAreRepacked)
{
    // Sixteen 64 tiles fill 256^2; keeping one in each quadrant leaves 12 tiles of free area but no free 128 block.
    ShadowAtlasPacker packer({.atlasSize = 256, .floorSize = 64, .maxSize = 256, .hysteresis = 0.0f});
    std::vector<ShadowTileRequest> requests;
    for (std::uint32_t i = 0; i < 16; ++i)
        requests.push_back({i, 64.0f, 1.0f});
    const ShadowAtlasPack full = packer.pack(requests);
    EXPECT_EQ(full.freeTexels, 0u);
    std::vector<ShadowTileRequest> kept;
    for (const PackedLight& light : full.lights)
        if (light.offsets[0].x % 128 == 0 && light.offsets[0].y % 128 == 0)
            kept.push_back({light.lightId, 64.0f, 1.0f});
    ASSERT_EQ(kept.size(), 4u);
    const ShadowAtlasPack scattered = packer.pack(kept);
    EXPECT_FALSE(scattered.repacked);
    EXPECT_EQ(scattered.largestFreeTile, 64u);
    EXPECT_NEAR(scattered.fragmentation, 1.0f - 1.0f / 12.0f, 1e-6f);
    kept.push_back({99, 128.0f, 1.0f});
    const ShadowAtlasPack repacked = packer.pack(kept);
    EXPECT_TRUE(repacked.repacked);
    EXPECT_EQ(repacked.lights.back().size, 128u);
    EXPECT_TRUE(repacked.notes.empty());
    expectDisjointPackedTiles(repacked, 256);
}

TEST(ShadowAtlasPacker, HoldsAThousandLights)
{
    ShadowAtlasPacker packer({.atlasSize = 8192, .floorSize = 64, .maxSize = 1024});
    std::vector<ShadowTileRequest> requests;
    for (std::uint32_t i = 0; i < 1024; ++i)
        requests.push_back({i, static_cast<float>(64 << (i % 5)), static_cast<float>(i % 97), i % 4 == 0 ? 6u : 1u});
    const auto start = std::chrono::steady_clock::now();
    const ShadowAtlasPack pack = packer.pack(requests);
    const auto placed = std::chrono::steady_clock::now();
    for (const PackedLight& light : pack.lights)
        EXPECT_NE(light.size, 0u) << light.lightId;
    const ShadowAtlasPack again = packer.pack(requests);
    std::printf("1024 lights: first frame %.2f ms, a still frame %.2f ms, fragmentation %.3f\n",
                std::chrono::duration<double, std::milli>(placed - start).count(),
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - placed).count(),
                again.fragmentation);
    for (const PackedLight& light : again.lights)
        EXPECT_FALSE(light.moved) << light.lightId;
}

TEST(ShadowAtlasPacker, OverlapCheckCatchesFault)
{
    ShadowAtlasPack pack;
    pack.lights = {{1, 128, 128, {{0, 0}}, true}, {2, 64, 64, {{64, 64}}, true}};
    EXPECT_NONFATAL_FAILURE(expectDisjointPackedTiles(pack, 256), "overlap");
}

TEST(ShadowAtlasPacker, RejectsBadSettingsAndRequestsNamingThem)
{
    const auto message = [](auto&& f) {
        try {
            f();
        } catch (const rhi::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message([] { ShadowAtlasPacker({.atlasSize = 3000}); }),
              "shadow atlas packer: atlasSize is 3000, allowed a power of two from 1 to 65536");
    EXPECT_EQ(message([] { ShadowAtlasPacker({.atlasSize = 1024, .floorSize = 64, .maxSize = 2048}); }),
              "shadow atlas packer: maxSize is 2048, allowed a power of two from 1 to 1024");
    EXPECT_EQ(message([] { ShadowAtlasPacker({.atlasSize = 1024, .floorSize = 512, .maxSize = 256}); }),
              "shadow atlas packer: floorSize is 512, allowed a power of two from 1 to 256");
    EXPECT_EQ(message([] { ShadowAtlasPacker({.atlasSize = 1024, .maxSize = 256, .hysteresis = 0.7f}); }),
              "shadow atlas packer: hysteresis is 0.7, allowed 0 to 0.5 octaves");
    ShadowAtlasPacker packer({.atlasSize = 1024, .floorSize = 64, .maxSize = 256});
    EXPECT_EQ(message([&] {
                  packer.pack(std::vector<ShadowTileRequest>{{1, 64.0f, 0.0f}, {1, 32.0f, 0.0f}});
              }),
              "shadow atlas packer: light 1 is requested twice in one frame");
    EXPECT_EQ(message([&] {
                  packer.pack(std::vector<ShadowTileRequest>{{4, 0.0f, 0.0f}});
              }),
              "shadow atlas packer: request 0 (light 4) asks for size 0, allowed a positive finite number of texels");
    EXPECT_EQ(message([&] {
                  packer.pack(std::vector<ShadowTileRequest>{{4, 1.0f, 0.0f, 0}});
              }),
              "shadow atlas packer: request 0 (light 4) asks for 0 tiles, allowed 1 or more");
}

} // namespace
} // namespace penumbra::shadows
