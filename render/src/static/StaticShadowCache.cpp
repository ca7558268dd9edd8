#include "StaticShadowCache.hpp"

#include "TileKeys.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/Light.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kStandInStaticAtlasSize = 16; // no map in use

std::uint64_t viewKey(const shadows::StaticShadowMap& map, const shadows::ShadowAtlas& atlas)
{
    ContentHash h;
    h.add(atlas.size()).add(atlas.format());
    for (const shadows::StaticShadowTile& tile : map.tiles)
        addTileView(h, tile);
    return h.value();
}

std::uint64_t casterKey(const shadows::StaticShadowMap& map, std::span<const shadows::ShadowCaster> casters)
{
    ContentHash h;
    for (const shadows::StaticShadowTile& tile : map.tiles)
        addTileCasters(h, tile, casters);
    return h.value();
}

bool isDirectional(const shadows::StaticShadowMap& map) { return map.kind == shadows::LightKind::Directional; }

std::vector<const shadows::StaticShadowMap*> mapsAt(const shadows::StaticShadowPlan& plan,
                                                    const std::vector<std::size_t>& indices)
{
    std::vector<const shadows::StaticShadowMap*> maps;
    for (std::size_t i : indices)
        maps.push_back(&plan.maps[i]);
    return maps;
}

// Window depths as writeTexture takes them for a depth format (rhi::Device::writeTexture).
std::vector<std::byte> depthTexels(const std::vector<float>& depth, rhi::Format format)
{
    std::vector<std::byte> bytes;
    const auto append = [&](const auto value) {
        const auto* first = reinterpret_cast<const std::byte*>(&value);
        bytes.insert(bytes.end(), first, first + sizeof(value));
    };
    for (const float d : depth) {
        const float clamped = std::clamp(d, 0.0f, 1.0f);
        if (format == rhi::Format::D16)
            append(static_cast<std::uint16_t>(std::lround(clamped * 65535.0f)));
        else if (format == rhi::Format::D24S8)
            append(static_cast<std::uint32_t>(std::lround(static_cast<double>(clamped) * 16777215.0)));
        else
            append(d);
    }
    return bytes;
}

// Whether two plans of a light's map put it in the same texels of its atlas.
bool sameTiles(const shadows::StaticShadowMap& a, const shadows::StaticShadowMap& b)
{
    if (a.tiles.size() != b.tiles.size())
        return false;
    for (std::size_t i = 0; i < a.tiles.size(); ++i) {
        const rhi::Viewport& x = a.tiles[i].viewport;
        const rhi::Viewport& y = b.tiles[i].viewport;
        if (a.tiles[i].tile != b.tiles[i].tile || x.x != y.x || x.y != y.y || x.width != y.width ||
            x.height != y.height)
            return false;
    }
    return true;
}

std::string mapName(const shadows::StaticShadowMap& map)
{
    return fmt::format("{} {}", scene::lightKindName(map.kind), map.lightIndex);
}

} // namespace

StaticShadowCache::StaticShadowCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat)
    : device_(device), pass_(device, vertexFormat)
{
    prepareAtlas(device_, directionalAtlas_, kStandInStaticAtlasSize, rhi::Format::D32F,
                 "static directional shadow atlas");
    prepareAtlas(device_, localAtlas_, kStandInStaticAtlasSize, rhi::Format::D32F, "static local shadow atlas");
}

bool StaticShadowCache::prepareAtlas(rhi::Device& device, std::unique_ptr<shadows::ShadowAtlas>& atlas,
                                     std::uint32_t size, rhi::Format format, const char* name)
{
    if (atlas && atlas->size() == size && atlas->format() == format)
        return false;
    atlas = std::make_unique<shadows::ShadowAtlas>(device, size, format, name);
    return true;
}

void StaticShadowCache::useBake(shadows::StaticShadowBake bake)
{
    bake_ = std::move(bake);
    drawn_.clear();
}

const shadows::BakedShadowMap* StaticShadowCache::bakedMap(const shadows::StaticShadowMap& map) const
{
    for (const shadows::BakedShadowMap& baked : bake_->maps)
        if (baked.kind == map.kind && baked.lightIndex == map.lightIndex)
            return &baked;
    return nullptr;
}

void StaticShadowCache::checkBake(const shadows::StaticShadowPlan& plan, std::span<const std::uint64_t> hashes) const
{
    if (!bake_)
        return;
    // A light the bake lacks first: it also reshapes the atlases, which would make every other map the wrong size.
    for (const shadows::StaticShadowMap& map : plan.maps)
        if (!bakedMap(map))
            throw rhi::Error(fmt::format("baked shadows (made on {}): no map for {}; bake the scene again",
                                         bake_->configuration, mapName(map)));
    for (std::size_t i = 0; i < plan.maps.size(); ++i) {
        const shadows::StaticShadowMap& map = plan.maps[i];
        const shadows::ShadowAtlasLayout& layout = isDirectional(map) ? plan.directionalAtlas : plan.localAtlas;
        const shadows::BakedShadowMap* baked = bakedMap(map);
        if (baked->size != layout.tileSize() || baked->frusta.size() != map.tiles.size())
            throw rhi::Error(fmt::format("baked shadows: {} ('{}') was baked as {} tiles of {} texels, the settings "
                                         "give {} of {}",
                                         mapName(map), baked->lightName, baked->frusta.size(), baked->size,
                                         map.tiles.size(), layout.tileSize()));
        if (baked->hash != hashes[i])
            throw rhi::Error(fmt::format("baked shadows: {} ('{}') is stale: the bake's hash {:016x}, the scene's "
                                         "{:016x} (the light, its shadow settings or a static caster in its view "
                                         "changed); bake the scene again",
                                         mapName(map), baked->lightName, baked->hash, hashes[i]));
    }
}

void StaticShadowCache::restore(shadows::ShadowAtlas& atlas, const shadows::ShadowAtlasLayout& layout,
                                const std::vector<const shadows::StaticShadowMap*>& maps)
{
    if (maps.empty())
        return;
    std::vector<float> depth(std::size_t(atlas.size()) * atlas.size(), device_.conventions().clearDepth());
    for (const shadows::StaticShadowMap* map : maps)
        shadows::restoreShadowMap(*bakedMap(*map), *map, layout, device_.conventions(), depth);
    device_.writeTexture(atlas.texture(), 0, 0, depthTexels(depth, atlas.format()));
}

const shadows::StaticShadowMap* StaticShadowCache::drawnMap(const shadows::StaticShadowMap& map) const
{
    for (const shadows::StaticShadowMap& old : plan_.maps)
        if (old.kind == map.kind && old.lightIndex == map.lightIndex)
            return &old;
    return nullptr;
}

void StaticShadowCache::keepDrawn(shadows::StaticShadowMap& map, shadows::StaticShadowUniforms& uniforms) const
{
    const shadows::StaticShadowMap& old = *drawnMap(map);
    const shadows::StaticShadowUniforms& was = plan_.uniforms;
    // The map's matrices, bounds, normal offsets and filter as drawn; the light's strength as it is now.
    if (isDirectional(map)) {
        const std::uint32_t tile = map.tiles.front().tile;
        uniforms.directionalWorldToMap[tile] = was.directionalWorldToMap[tile];
        uniforms.directionalBounds[tile] = was.directionalBounds[tile];
        if (map.litIndex < shadows::maxStaticMapDirectionalLights &&
            old.litIndex < shadows::maxStaticMapDirectionalLights) {
            const float strength = uniforms.directionalLights[map.litIndex].strength;
            uniforms.directionalLights[map.litIndex] = was.directionalLights[old.litIndex];
            uniforms.directionalLights[map.litIndex].strength = strength;
        }
    } else {
        for (const shadows::StaticShadowTile& tile : map.tiles) {
            uniforms.localWorldToMap[tile.tile] = was.localWorldToMap[tile.tile];
            uniforms.localBounds[tile.tile] = was.localBounds[tile.tile];
            uniforms.localTiles[tile.tile] = was.localTiles[tile.tile];
        }
    }
    const std::uint32_t litIndex = map.litIndex;
    const shadows::StaticShadowUpdate update = map.update;
    map = old;
    map.litIndex = litIndex;
    map.update = update;
}

StaticMapDraws StaticShadowCache::prepare(const shadows::ShadowSettings& settings, shadows::StaticShadowPlan plan,
                                          std::span<const shadows::ShadowCaster> casters, bool requested)
{
    const auto sizeOf = [](const shadows::ShadowAtlasLayout& layout) {
        return layout.tileCount() > 0 ? layout.atlasSize() : kStandInStaticAtlasSize;
    };
    const bool directionalNew = prepareAtlas(device_, directionalAtlas_, sizeOf(plan.directionalAtlas),
                                             settings.directional.atlasFormat, "static directional shadow atlas");
    const bool localNew = prepareAtlas(device_, localAtlas_, sizeOf(plan.localAtlas), settings.local.atlasFormat,
                                       "static local shadow atlas");
    StaticMapDraws draws;
    std::map<LightId, Key> keys;
    std::vector<std::size_t> directionalMaps, localMaps; // indices into plan.maps
    for (std::size_t i = 0; i < plan.maps.size(); ++i) {
        shadows::StaticShadowMap& map = plan.maps[i];
        const bool directional = isDirectional(map);
        const bool atlasNew = directional ? directionalNew : localNew;
        const LightId id{map.kind, map.lightIndex};
        const auto old = drawn_.find(id);
        // On demand, a map drawn before stays as drawn while it keeps its tiles, whatever changed since.
        if (map.update == shadows::StaticShadowUpdate::OnDemand && !requested && !atlasNew && old != drawn_.end() &&
            sameTiles(*drawnMap(map), map)) {
            keepDrawn(map, plan.uniforms);
            keys.emplace(id, old->second);
            continue;
        }
        const Key key{viewKey(map, directional ? *directionalAtlas_ : *localAtlas_), casterKey(map, casters)};
        const char* reason = redrawReason(map, old == drawn_.end() ? nullptr : &old->second, key, atlasNew, requested);
        if (reason) {
            draws.updates.push_back({map.kind, map.lightIndex, reason});
            (directional ? directionalMaps : localMaps).push_back(i);
        }
        keys.emplace(id, key);
    }
    drawn_ = std::move(keys);
    plan_ = std::move(plan);
    pendingDirectional_.clear();
    pendingLocal_.clear();
    directionalNew_ = false;
    localNew_ = false;
    if (bake_) {
        // A restore rewrites the whole atlas, so every map of its kind is restored with the one that changed.
        for (StaticMapUpdate& u : draws.updates)
            u.reason = "restored from the bake";
        if (!directionalMaps.empty())
            restore(*directionalAtlas_, plan_.directionalAtlas, mapsOfKind(true));
        if (!localMaps.empty())
            restore(*localAtlas_, plan_.localAtlas, mapsOfKind(false));
        return draws;
    }
    pendingDirectional_ = mapsAt(plan_, directionalMaps);
    pendingLocal_ = mapsAt(plan_, localMaps);
    directionalNew_ = directionalNew;
    localNew_ = localNew;
    return draws;
}

const char* StaticShadowCache::redrawReason(const shadows::StaticShadowMap& map, const Key* drawn, const Key& key,
                                            bool atlasNew, bool requested)
{
    if (!drawn)
        return "first drawn";
    if (atlasNew)
        return "its static atlas was created anew";
    if (requested)
        return "asked for";
    if (map.update == shadows::StaticShadowUpdate::OnDemand)
        return "its tiles moved in the static atlas";
    if (drawn->view != key.view)
        return "its view changed (the light, its shadow settings or the static casters' bounds)";
    if (drawn->casters != key.casters)
        return "a static caster in its view changed";
    return nullptr;
}

std::vector<const shadows::StaticShadowMap*> StaticShadowCache::mapsOfKind(bool directional) const
{
    std::vector<const shadows::StaticShadowMap*> maps;
    for (const shadows::StaticShadowMap& map : plan_.maps)
        if (isDirectional(map) == directional)
            maps.push_back(&map);
    return maps;
}

std::uint32_t StaticShadowCache::record(rhi::CommandList& commands, std::span<const shadows::ShadowCaster> casters)
{
    const auto tilesOf = [](const std::vector<const shadows::StaticShadowMap*>& maps) {
        std::vector<const shadows::ShadowTileDraw*> tiles;
        for (const shadows::StaticShadowMap* map : maps)
            for (const shadows::StaticShadowTile& tile : map->tiles)
                tiles.push_back(&tile);
        return tiles;
    };
    if (!drawsPending())
        return 0;
    pass_.begin();
    std::uint32_t draws = 0;
    if (!pendingDirectional_.empty() || directionalNew_)
        draws += pass_.record(commands, *directionalAtlas_, tilesOf(pendingDirectional_), casters, directionalNew_);
    if (!pendingLocal_.empty() || localNew_)
        draws += pass_.record(commands, *localAtlas_, tilesOf(pendingLocal_), casters, localNew_);
    return draws;
}

} // namespace penumbra::render
