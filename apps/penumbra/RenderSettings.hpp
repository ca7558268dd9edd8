#pragma once

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <filesystem>
#include <optional>

namespace penumbra::apps {

// A --settings file: the shadow settings' JSON (shadows::parseShadowSettings) with an optional top-level "ambient"
// object: {"color": [r, g, b], "intensity": i, "ground": [r, g, b]} (render::AmbientLight; each field optional,
// "ground" makes it a sky/ground hemisphere).
struct RenderSettings {
    shadows::ShadowSettings shadows;
    std::optional<render::AmbientLight> ambient;
};

// Throws rhi::Error "<path>: <field>: <what>" for an unreadable file, bad JSON, an unknown field or a value out of
// range.
RenderSettings loadRenderSettings(const std::filesystem::path& path);

} // namespace penumbra::apps
