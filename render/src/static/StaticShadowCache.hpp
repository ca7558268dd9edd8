#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"
#include "penumbra/shadows/StaticShadowPass.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::render {

// One static map drawn this frame, and why.
struct StaticMapUpdate {
    shadows::LightKind kind = shadows::LightKind::Directional;
    std::uint32_t lightIndex = 0;
    std::string reason;
};

// What a frame drew into the static atlases.
struct StaticMapDraws {
    std::vector<StaticMapUpdate> updates;
    std::uint32_t casterDraws = 0;
};

// The static shadow maps kept between frames: the two static atlases, and per light the map's key as last drawn (its
// views and the static casters in them), so a frame draws again only the maps whose key changed, in OnChange mode,
// or that the application asked for, in OnDemand mode.
class StaticShadowCache {
public:
    StaticShadowCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat);

    // Takes this frame's plan and chooses the maps it needs drawn, which record() then draws; returns those maps
    // (their caster draws are record()'s). A map in OnChange mode is drawn when its key changed; one in OnDemand mode
    // (StaticShadowMap::update, the light's own or the settings'), unless `requested`, keeps the tiles and uniforms it
    // was drawn with while its atlas and its tiles stay, whatever else changed. `requested` draws every map. Without
    // maps the atlases are small stand-ins. With a bake, the chosen maps' atlases are restored (uploaded) here.
    StaticMapDraws prepare(const shadows::ShadowSettings& settings, shadows::StaticShadowPlan plan,
                           std::span<const shadows::ShadowCaster> casters, bool requested);
    // Records the draws prepare() chose (none with a bake); returns the caster draws. `casters` are prepare()'s.
    std::uint32_t record(rhi::CommandList& commands, std::span<const shadows::ShadowCaster> casters);
    // Whether record() has anything to draw or clear.
    bool drawsPending() const
    {
        return !pendingDirectional_.empty() || !pendingLocal_.empty() || directionalNew_ || localNew_;
    }

    // From now on the maps come from `bake`: update() restores them into the atlases instead of drawing casters.
    void useBake(shadows::StaticShadowBake bake);
    bool baked() const { return bake_.has_value(); }
    // With a bake: throws rhi::Error naming the light and what differs (no map for it, another size or tile count,
    // another hash: the light, its settings or the static casters changed since the bake) unless the bake holds
    // every map of `plan`; `hashes` are staticMapHashes(plan).
    void checkBake(const shadows::StaticShadowPlan& plan, std::span<const std::uint64_t> hashes) const;

    const shadows::ShadowAtlas& directionalAtlas() const { return *directionalAtlas_; }
    const shadows::ShadowAtlas& localAtlas() const { return *localAtlas_; }
    // The maps as drawn.
    const shadows::StaticShadowPlan& plan() const { return plan_; }

private:
    struct Key {
        std::uint64_t view = 0; // tiles, viewports, matrices, biases
        std::uint64_t casters = 0; // the static casters drawn and what they are
    };
    using LightId = std::pair<shadows::LightKind, std::uint32_t>;

    // Whether the atlas had to be created anew (its old tiles are gone).
    static bool prepareAtlas(rhi::Device& device, std::unique_ptr<shadows::ShadowAtlas>& atlas, std::uint32_t size,
                             rhi::Format format, const char* name);

    rhi::Device& device_;
    shadows::StaticShadowPass pass_;
    std::unique_ptr<shadows::ShadowAtlas> directionalAtlas_;
    std::unique_ptr<shadows::ShadowAtlas> localAtlas_;
    shadows::StaticShadowPlan plan_;
    std::map<LightId, Key> drawn_;
    std::optional<shadows::StaticShadowBake> bake_;
    // What prepare() left record() to draw: maps of plan_, and whether each atlas is new (then cleared whole).
    std::vector<const shadows::StaticShadowMap*> pendingDirectional_, pendingLocal_;
    bool directionalNew_ = false;
    bool localNew_ = false;

    const shadows::BakedShadowMap* bakedMap(const shadows::StaticShadowMap& map) const;
    // Why a map is drawn again this frame (`drawn`: its key as last drawn, or nullptr), or nullptr.
    static const char* redrawReason(const shadows::StaticShadowMap& map, const Key* drawn, const Key& key,
                                    bool atlasNew, bool requested);
    // The maps of plan_ in the directional atlas, or in the local one.
    std::vector<const shadows::StaticShadowMap*> mapsOfKind(bool directional) const;
    // The light's map as last drawn (in plan_), or nullptr.
    const shadows::StaticShadowMap* drawnMap(const shadows::StaticShadowMap& map) const;
    // Replaces `map` and its entries of `uniforms` with the map as last drawn (strength stays `uniforms`').
    void keepDrawn(shadows::StaticShadowMap& map, shadows::StaticShadowUniforms& uniforms) const;
    // Restores every map of the plan (of the one kind of atlas) from the bake: one upload of the whole atlas.
    void restore(shadows::ShadowAtlas& atlas, const shadows::ShadowAtlasLayout& layout,
                 const std::vector<const shadows::StaticShadowMap*>& maps);
};

} // namespace penumbra::render
