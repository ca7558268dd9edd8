#include "RenderSettings.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace penumbra::apps {
namespace {

using Json = nlohmann::json;

glm::vec3 colorOf(const Json& value, const std::string& source, const char* field)
{
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
        !value[2].is_number())
        throw rhi::Error(fmt::format("{}: {}: {} is not an array of 3 numbers, allowed [r, g, b] each at least 0",
                                     source, field, value.dump()));
    return {value[0].get<float>(), value[1].get<float>(), value[2].get<float>()};
}

EnvironmentSetting environmentOf(const Json& object, const std::string& source)
{
    if (!object.is_object())
        throw rhi::Error(fmt::format("{}: environment: {} is not an object, allowed fields source, intensity, rotation",
                                     source, object.dump()));
    EnvironmentSetting environment;
    for (const auto& [key, value] : object.items()) {
        if (key == "source") {
            if (!value.is_string())
                throw rhi::Error(fmt::format("{}: environment.source: {} is not a string (a .hdr or .exr file, "
                                             "default, none or auto)",
                                             source, value.dump()));
            environment.source = value.get<std::string>();
        } else if (key == "intensity" || key == "rotation") {
            const bool intensity = key == "intensity";
            const float low = intensity ? 0.0f : -360.0f;
            const float high = intensity ? render::kMaxEnvironmentIntensity : 360.0f;
            if (!value.is_number() || value.get<float>() < low || value.get<float>() > high)
                throw rhi::Error(fmt::format("{}: environment.{}: {} is not a number from {} to {}", source, key,
                                             value.dump(), low, high));
            (intensity ? environment.intensity : environment.rotation) = value.get<float>();
        } else {
            throw rhi::Error(
                fmt::format("{}: environment.{}: unknown field, allowed source, intensity, rotation", source, key));
        }
    }
    return environment;
}

render::AmbientLight ambientOf(const Json& object, const std::string& source)
{
    if (!object.is_object())
        throw rhi::Error(fmt::format("{}: ambient: {} is not an object, allowed fields color, intensity, ground",
                                     source, object.dump()));
    render::AmbientLight ambient;
    for (const auto& [key, value] : object.items()) {
        if (key == "color") {
            ambient.color = colorOf(value, source, "ambient.color");
        } else if (key == "ground") {
            ambient.ground = colorOf(value, source, "ambient.ground");
        } else if (key == "intensity") {
            if (!value.is_number())
                throw rhi::Error(fmt::format("{}: ambient.intensity: {} is not a number, allowed 0 to {}", source,
                                             value.dump(), render::kMaxAmbientIntensity));
            ambient.intensity = value.get<float>();
        } else {
            throw rhi::Error(
                fmt::format("{}: ambient.{}: unknown field, allowed color, intensity, ground", source, key));
        }
    }
    try {
        render::validate(ambient);
    } catch (const rhi::Error& e) {
        throw rhi::Error(fmt::format("{}: {}", source, e.what()));
    }
    return ambient;
}

float anisotropyOf(const Json& value, const std::string& source)
{
    if (!value.is_number() || value.get<float>() < 1.0f || value.get<float>() > kMaxAnisotropyOption)
        throw rhi::Error(fmt::format("{}: anisotropy: {} is not a number from 1 (off) to {}", source, value.dump(),
                                     kMaxAnisotropyOption));
    return value.get<float>();
}

std::uint32_t msaaOf(const Json& value, const std::string& source)
{
    const bool allowed = value.is_number_integer() && std::find(std::begin(kMsaaCounts), std::end(kMsaaCounts),
                                                                value.get<std::int64_t>()) != std::end(kMsaaCounts);
    if (!allowed)
        throw rhi::Error(fmt::format("{}: msaa: {} is not a sample count, allowed 1, 2, 4 or 8", source, value.dump()));
    return value.get<std::uint32_t>();
}

render::ShadowPath shadowPathOf(const Json& value, const std::string& source)
{
    const std::optional<render::ShadowPath> path =
        value.is_string() ? parseShadowPath(value.get<std::string>()) : std::nullopt;
    if (!path)
        throw rhi::Error(fmt::format("{}: shadowPath: {} is not a shadow path, allowed {}", source, value.dump(),
                                     fmt::join(kShadowPathNames, ", ")));
    return *path;
}

} // namespace

std::optional<render::ShadowPath> parseShadowPath(std::string_view name)
{
    for (std::size_t i = 0; i < std::size(kShadowPathNames); ++i)
        if (name == kShadowPathNames[i])
            return static_cast<render::ShadowPath>(i);
    return std::nullopt;
}

RenderSettings loadRenderSettings(const std::filesystem::path& path)
{
    const std::string source = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open: {}", source, std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    RenderSettings settings;
    // The ambient object is this tool's; the rest is the shadow settings' JSON, whose parser names its own errors
    // (bad JSON included).
    Json root = Json::parse(text.str(), nullptr, false);
    if (!root.is_object() || (!root.contains("ambient") && !root.contains("environment") &&
                              !root.contains("anisotropy") && !root.contains("msaa") && !root.contains("shadowPath"))) {
        settings.shadows = shadows::parseShadowSettings(text.str(), source);
        return settings;
    }
    if (root.contains("ambient")) {
        settings.ambient = ambientOf(root["ambient"], source);
        root.erase("ambient");
    }
    if (root.contains("environment")) {
        settings.environment = environmentOf(root["environment"], source);
        root.erase("environment");
    }
    if (root.contains("anisotropy")) {
        settings.anisotropy = anisotropyOf(root["anisotropy"], source);
        root.erase("anisotropy");
    }
    if (root.contains("msaa")) {
        settings.msaa = msaaOf(root["msaa"], source);
        root.erase("msaa");
    }
    if (root.contains("shadowPath")) {
        settings.shadowPath = shadowPathOf(root["shadowPath"], source);
        root.erase("shadowPath");
    }
    settings.shadows = shadows::parseShadowSettings(root.dump(), source);
    return settings;
}

} // namespace penumbra::apps
