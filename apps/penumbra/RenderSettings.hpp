#pragma once

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra::apps {

// A --settings file: the shadow settings' JSON (shadows::parseShadowSettings) with an optional top-level "ambient"
// object: {"color": [r, g, b], "intensity": i, "ground": [r, g, b]} (render::AmbientLight; each field optional,
// "ground" makes it a sky/ground hemisphere), an optional top-level "anisotropy" number, 1 to
// kMaxAnisotropyOption (render::FrameDesc::maxAnisotropy), an optional top-level "msaa" sample count, 1, 2, 4
// or 8 (render::FrameDesc::msaa), and an optional top-level "shadowPath", one of kShadowPathNames
// (render::FrameDesc::shadowPath).
// The settings' optional top-level "environment" object: {"source": kEnvironmentSyntax, "intensity": i, "rotation":
// degrees}, each field optional (render::EnvironmentLight; a relative file is read from the working directory).
struct EnvironmentSetting {
    std::string source = "auto";
    float intensity = 1.0f;
    float rotation = 0.0f;
};

struct RenderSettings {
    shadows::ShadowSettings shadows;
    std::optional<render::AmbientLight> ambient;
    std::optional<EnvironmentSetting> environment;
    std::optional<float> anisotropy;
    std::optional<std::uint32_t> msaa;
    std::optional<render::ShadowPath> shadowPath;
};

// render::ShadowPath's names, in its order: in the settings' "shadowPath" and on the command line (--shadow-path).
inline constexpr const char* kShadowPathNames[] = {"forward", "screenSpace"};

// One of kShadowPathNames, or nullopt.
std::optional<render::ShadowPath> parseShadowPath(std::string_view name);

// The sample counts --msaa and the settings' "msaa" take (render::FrameDesc::msaa); the device may offer fewer.
inline constexpr std::uint32_t kMsaaCounts[] = {1, 2, 4, 8};

// 16: what Vulkan requires of devices with samplerAnisotropy (the specification's Required Limits table,
// maxSamplerAnisotropy) and more than GPUs offer.
inline constexpr float kMaxAnisotropyOption = 16.0f;

// Throws rhi::Error "<path>: <field>: <what>" for an unreadable file, bad JSON, an unknown field or a value out of
// range.
RenderSettings loadRenderSettings(const std::filesystem::path& path);

} // namespace penumbra::apps
