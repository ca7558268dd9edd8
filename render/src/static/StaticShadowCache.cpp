#include "StaticShadowCache.hpp"

#include <cstring>
#include <type_traits>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kStandInAtlasSize = 16; // no map in use

// FNV-1a over the bytes of plain values: a map's key only has to change when what it was drawn from changes.
class Hasher {
public:
    template <typename T>
    Hasher& add(const T& value)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (const unsigned char b : bytes)
            hash_ = (hash_ ^ b) * 1099511628211ull;
        return *this;
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

std::uint64_t viewKey(const shadows::StaticShadowMap& map, const shadows::ShadowAtlas& atlas)
{
    Hasher h;
    h.add(atlas.size()).add(atlas.format());
    for (const shadows::StaticShadowTile& tile : map.tiles) {
        const shadows::ShadowViewDraw& v = tile.view;
        h.add(tile.tile).add(tile.viewport).add(v.viewProjection).add(v.slopeScaleBias).add(v.pancake).add(v.mirrored);
        h.add(v.ditherOrigin).add(v.normalOffset.reach).add(v.normalOffset.light);
    }
    return h.value();
}

std::uint64_t casterKey(const shadows::StaticShadowMap& map, std::span<const shadows::ShadowCaster> casters)
{
    Hasher h;
    for (const shadows::StaticShadowTile& tile : map.tiles)
        for (const std::uint32_t i : tile.casters) {
            const shadows::ShadowCaster& c = casters[i];
            h.add(i).add(c.vertices).add(c.indices).add(c.indexCount).add(c.model).add(c.mode).add(c.alpha);
            h.add(c.alphaCutoff).add(c.baseColorMap).add(c.textured).add(c.baseColorUv).add(c.doubleSided);
        }
    return h.value();
}

bool isDirectional(const shadows::StaticShadowMap& map) { return map.kind == shadows::ShadowLightKind::Directional; }

} // namespace

StaticShadowCache::StaticShadowCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat)
    : device_(device), pass_(device, vertexFormat)
{
    prepareAtlas(device_, directionalAtlas_, kStandInAtlasSize, rhi::Format::D32F, "static directional shadow atlas");
    prepareAtlas(device_, otherAtlas_, kStandInAtlasSize, rhi::Format::D32F, "static other shadow atlas");
}

bool StaticShadowCache::prepareAtlas(rhi::Device& device, std::unique_ptr<shadows::ShadowAtlas>& atlas,
                                     std::uint32_t size, rhi::Format format, const char* name)
{
    if (atlas && atlas->size() == size && atlas->format() == format)
        return false;
    atlas = std::make_unique<shadows::ShadowAtlas>(device, size, format, name);
    return true;
}

StaticMapDraws StaticShadowCache::update(rhi::CommandList& commands, const shadows::ShadowSettings& settings,
                                         shadows::StaticShadowPlan plan, std::span<const shadows::ShadowCaster> casters,
                                         bool requested)
{
    const bool onDemand = settings.staticMaps.update == shadows::StaticShadowUpdate::OnDemand;
    const auto sizeOf = [](const shadows::ShadowAtlasLayout& layout) {
        return layout.tileCount() > 0 ? layout.atlasSize() : kStandInAtlasSize;
    };
    // On demand, what was drawn stays while its atlases can: the settings' sizes and formats still describe them.
    const bool atlasesKept = sizeOf(plan.directionalAtlas) == sizeOf(plan_.directionalAtlas) &&
                             sizeOf(plan.otherAtlas) == sizeOf(plan_.otherAtlas) &&
                             directionalAtlas_->format() == settings.directional.atlasFormat &&
                             otherAtlas_->format() == settings.other.atlasFormat;
    if (onDemand && !requested && hasPlan_ && atlasesKept)
        return {};
    const bool directionalNew = prepareAtlas(device_, directionalAtlas_, sizeOf(plan.directionalAtlas),
                                             settings.directional.atlasFormat, "static directional shadow atlas");
    const bool otherNew = prepareAtlas(device_, otherAtlas_, sizeOf(plan.otherAtlas), settings.other.atlasFormat,
                                       "static other shadow atlas");
    StaticMapDraws draws;
    std::map<LightId, Key> keys;
    std::vector<const shadows::StaticShadowMap*> directionalMaps, otherMaps;
    for (const shadows::StaticShadowMap& map : plan.maps) {
        const bool directional = isDirectional(map);
        const Key key{viewKey(map, directional ? *directionalAtlas_ : *otherAtlas_), casterKey(map, casters)};
        const LightId id{map.kind, map.lightIndex};
        const auto old = drawn_.find(id);
        const char* reason = nullptr;
        if (old == drawn_.end())
            reason = "first drawn";
        else if (directional ? directionalNew : otherNew)
            reason = "its static atlas was created anew";
        else if (requested)
            reason = "asked for";
        else if (old->second.view != key.view)
            reason = "its view changed (the light, its shadow settings or the static casters' bounds)";
        else if (old->second.casters != key.casters)
            reason = "a static caster in its view changed";
        if (reason) {
            draws.updates.push_back({map.kind, map.lightIndex, reason});
            (directional ? directionalMaps : otherMaps).push_back(&map);
        }
        keys.emplace(id, key);
    }
    if (!directionalMaps.empty() || directionalNew)
        draws.casterDraws += pass_.record(commands, *directionalAtlas_, directionalMaps, casters, directionalNew);
    if (!otherMaps.empty() || otherNew)
        draws.casterDraws += pass_.record(commands, *otherAtlas_, otherMaps, casters, otherNew);
    drawn_ = std::move(keys);
    plan_ = std::move(plan);
    hasPlan_ = true;
    return draws;
}

} // namespace penumbra::render
