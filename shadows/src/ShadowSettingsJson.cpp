#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace penumbra::shadows {
namespace {

// The enum value of a field of names by one of its names.
std::optional<int> shadowFieldValueOf(std::string_view path, std::string_view name)
{
    for (const settings::SettingName& entry : shadowSettingsField(path).names)
        if (entry.name == name)
            return entry.value;
    return std::nullopt;
}

} // namespace

std::string settingsFieldText(const ShadowSettings& settings, std::string_view path)
{
    return shadowSettingsTable().text(settings, path);
}

void setSettingsField(ShadowSettings& settings, std::string_view path, std::string_view text)
{
    shadowSettingsTable().set(settings, path, text);
}

std::optional<StaticShadowUpdate> parseStaticShadowUpdate(std::string_view name)
{
    const std::optional<int> value = shadowFieldValueOf("static.update", name);
    return value ? std::optional(static_cast<StaticShadowUpdate>(*value)) : std::nullopt;
}

std::optional<RealtimeCasters> parseRealtimeCasters(std::string_view name)
{
    const std::optional<int> value = shadowFieldValueOf("static.realtimeCasters", name);
    return value ? std::optional(static_cast<RealtimeCasters>(*value)) : std::nullopt;
}

ShadowSettings parseShadowSettings(std::string_view json, std::string_view sourceName)
{
    ShadowSettings settings;
    shadowSettingsTable().read(json, sourceName, settings);
    return settings;
}

std::string toJson(const ShadowSettings& settings) { return shadowSettingsTable().toJson(settings); }

ShadowSettings loadShadowSettings(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw rhi::Error(fmt::format("{}: cannot read: {}", path.string(), std::strerror(errno)));
    return parseShadowSettings(text.str(), path.string());
}

void saveShadowSettings(const std::filesystem::path& path, const ShadowSettings& settings)
{
    validate(settings);
    rhi::writeFileAtomically(path, toJson(settings));
}

} // namespace penumbra::shadows
