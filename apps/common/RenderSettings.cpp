#include "RenderSettings.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace penumbra::apps {

bool isRenderLevelField(std::string_view path) { return shadows::shadowSettingsTable().find(path) == nullptr; }

std::string_view shadowPathName(render::ShadowPath path)
{
    for (const settings::SettingName& entry : renderSettingsTable().field("shadowPath").names)
        if (entry.value == static_cast<int>(path))
            return entry.name;
    return "";
}

std::vector<std::string_view> loadRenderSettings(const std::filesystem::path& path, RenderSettings& settings)
{
    const std::string source = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open: {}", source, std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    return renderSettingsTable().read(text.str(), source, settings);
}

void applySettingsFieldValues(RenderSettings& settings, const SettingsFieldValues& values)
{
    for (const auto& [path, text] : values)
        renderSettingsTable().set(settings, path, text);
}

} // namespace penumbra::apps
