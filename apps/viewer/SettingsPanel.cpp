#include "RenderSettings.hpp"
#include "ViewState.hpp"

#include "penumbra/rhi/Format.hpp"

#include <algorithm>
#include <optional>
#include <array>
#include <cctype>
#include <fmt/format.h>
#include <imgui.h>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra::viewer {
namespace {

template <typename Enum, std::size_t N>
bool enumCombo(const char* label, Enum& value, const std::array<const char*, N>& names)
{
    int index = static_cast<int>(value);
    const bool changed = ImGui::Combo(label, &index, names.data(), int(N));
    if (changed)
        value = static_cast<Enum>(index);
    return changed;
}

// shadows::ShadowFilter's command-line names, in its order.
std::array<const char*, shadows::kShadowFilterCount> filterNames()
{
    std::array<const char*, shadows::kShadowFilterCount> names{};
    for (std::size_t i = 0; i < names.size(); ++i)
        names[i] = shadows::shadowFilters()[i].command.data();
    return names;
}

bool filterCombo(const char* label, shadows::ShadowFilter& filter) { return enumCombo(label, filter, filterNames()); }

// A settings field's control is written from its entry in apps::renderSettingsTable() (the render-level fields and
// the shadow settings'): the label is the path's last name in words ("soft.blockerSearchScale": "blocker search
// scale"), the range or the names are the field's, and its summary shows while the pointer is on it.
const settings::SettingsFieldInfo& settingsFieldAt(std::string_view path)
{
    return apps::renderSettingsTable().field(path);
}

std::string labelOf(std::string_view path)
{
    std::string label;
    for (const char c : path.substr(path.rfind('.') + 1)) {
        if (std::isupper(static_cast<unsigned char>(c))) {
            label += ' ';
            label += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else {
            label += c;
        }
    }
    return label;
}

void summaryTooltip(const settings::SettingsFieldInfo& field)
{
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", std::string(field.summary).c_str());
}

// One of `names` by its index; true when the choice changed.
bool indexCombo(const char* label, std::size_t& index, const std::vector<std::string>& names)
{
    bool changed = false;
    if (ImGui::BeginCombo(label, index < names.size() ? names[index].c_str() : "")) {
        for (std::size_t i = 0; i < names.size(); ++i)
            if (ImGui::Selectable(names[i].c_str(), i == index)) {
                changed = i != index;
                index = i;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// A field of listed names ("hard, soft, dither"), the enum's values in the names' order.
template <typename Enum>
bool fieldCombo(std::string_view path, Enum& value)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt(path);
    std::vector<std::string> names;
    for (std::size_t start = 0; start <= field.allowed.size();) {
        const std::size_t end = std::min(field.allowed.find(", ", start), field.allowed.size());
        names.push_back(field.allowed.substr(start, end - start));
        start = end + 2;
    }
    auto index = static_cast<std::size_t>(value);
    const bool changed = indexCombo(labelOf(path).c_str(), index, names);
    summaryTooltip(field);
    if (changed)
        value = static_cast<Enum>(index);
    return changed;
}

bool fieldSlider(std::string_view path, float& value)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt(path);
    const bool changed = ImGui::SliderFloat(labelOf(path).c_str(), &value, static_cast<float>(field.range.low),
                                            static_cast<float>(field.range.high));
    summaryTooltip(field);
    return changed;
}

bool fieldSlider(std::string_view path, std::uint32_t& value)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt(path);
    int v = static_cast<int>(value);
    const bool changed = ImGui::SliderInt(labelOf(path).c_str(), &v, static_cast<int>(field.range.low),
                                          static_cast<int>(field.range.high));
    summaryTooltip(field);
    if (changed)
        value = static_cast<std::uint32_t>(v);
    return changed;
}

// A field whose range spans decades (a constant depth bias, 0 to a million steps): the slider moves logarithmically.
bool fieldLogSlider(std::string_view path, float& value, const char* format = "%.0f")
{
    const settings::SettingsFieldInfo& field = settingsFieldAt(path);
    const bool changed = ImGui::SliderFloat(labelOf(path).c_str(), &value, static_cast<float>(field.range.low),
                                            static_cast<float>(field.range.high), format, ImGuiSliderFlags_Logarithmic);
    summaryTooltip(field);
    return changed;
}

// The powers of two of the field's range.
bool fieldPowerOfTwo(std::string_view path, std::uint32_t& value)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt(path);
    std::vector<std::string> names;
    std::size_t index = names.size();
    for (auto size = static_cast<std::uint32_t>(field.range.low); size <= field.range.high; size *= 2) {
        if (size == value)
            index = names.size();
        names.push_back(std::to_string(size));
    }
    const bool changed = indexCombo(labelOf(path).c_str(), index, names);
    summaryTooltip(field);
    if (changed)
        value = static_cast<std::uint32_t>(field.range.low) << index;
    return changed;
}

// A light's own option, or none of its own (the first name: the settings' value).
template <typename Enum, std::size_t N>
bool optionalEnumCombo(const char* label, std::optional<Enum>& value, const std::array<const char*, N>& names)
{
    int index = value ? static_cast<int>(*value) + 1 : 0;
    const bool changed = ImGui::Combo(label, &index, names.data(), int(N));
    if (changed)
        value = index == 0 ? std::nullopt : std::optional<Enum>(static_cast<Enum>(index - 1));
    return changed;
}

// A light's own filter: "atlas" (the settings' filter) or one of the filters.
bool lightFilterCombo(std::optional<shadows::ShadowFilter>& filter)
{
    std::array<const char*, shadows::kShadowFilterCount + 1> names{"atlas"};
    for (std::size_t i = 0; i < shadows::kShadowFilterCount; ++i)
        names[i + 1] = filterNames()[i];
    return optionalEnumCombo("shadow filter", filter, names);
}

// One of shadows::kPoissonSampleCounts.
bool sampleCountCombo(std::string_view path, std::uint32_t& count)
{
    std::vector<std::string> names;
    std::size_t index = 0;
    for (const std::uint32_t offered : shadows::kPoissonSampleCounts) {
        if (offered == count)
            index = names.size();
        names.push_back(std::to_string(offered));
    }
    const bool changed = indexCombo(labelOf(path).c_str(), index, names);
    summaryTooltip(settingsFieldAt(path));
    if (changed)
        count = shadows::kPoissonSampleCounts[index];
    return changed;
}

bool softSettings(shadows::SoftShadowSettings& s)
{
    bool changed = false;
    changed |= fieldSlider("soft.blockerSearchScale", s.blockerSearchScale);
    changed |= fieldSlider("soft.penumbraScale", s.penumbraScale);
    changed |= sampleCountCombo("soft.blockerSamples", s.blockerSamples);
    changed |= sampleCountCombo("soft.filterSamples", s.filterSamples);
    changed |= fieldSlider("soft.minPenumbraTexels", s.minPenumbraTexels);
    changed |= fieldSlider("soft.maxPenumbraTexels", s.maxPenumbraTexels);
    changed |= fieldSlider("soft.poissonRadiusTexels", s.poissonRadiusTexels);
    changed |= fieldCombo("soft.diskRotation", s.diskRotation);
    return changed;
}

bool atlasFormatCombo(rhi::Format& format)
{
    constexpr std::array formats{rhi::Format::D16, rhi::Format::D24S8, rhi::Format::D32F};
    bool changed = false;
    if (ImGui::BeginCombo("atlas format", std::string(rhi::formatName(format)).c_str())) {
        for (rhi::Format f : formats)
            if (ImGui::Selectable(std::string(rhi::formatName(f)).c_str(), f == format)) {
                changed = f != format;
                format = f;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// The widgets' ranges and names are the settings fields' (settingsFieldAt); values typed in
// (ctrl+click) may leave a range, and validation then reports the field.
bool shadowSettings(shadows::ShadowSettings& s)
{
    bool changed = false;
    // Above its lower bound, the shadow distance drags as far as a kilometre.
    const settings::SettingsFieldInfo& maxDistance = settingsFieldAt("maxDistance");
    changed |= ImGui::DragFloat(labelOf(maxDistance.path).c_str(), &s.maxDistance, 0.5f,
                                static_cast<float>(maxDistance.range.low), 1000.0f);
    summaryTooltip(maxDistance);
    changed |= fieldSlider("distanceFade", s.distanceFade);
    changed |= fieldCombo("culling", s.culling);
    shadows::DirectionalShadowSettings& d = s.directional;
    changed |= fieldPowerOfTwo("directional.atlasSize", d.atlasSize);
    changed |= atlasFormatCombo(d.atlasFormat);
    changed |= filterCombo("filter", d.filter);
    changed |= fieldSlider("directional.cascadeCount", d.cascadeCount);
    const settings::SettingsFieldInfo& ratios = settingsFieldAt("directional.cascadeRatios");
    changed |= ImGui::SliderFloat3(labelOf(ratios.path).c_str(), &d.cascadeRatios.x,
                                   static_cast<float>(ratios.range.low), static_cast<float>(ratios.range.high));
    summaryTooltip(ratios);
    changed |= fieldSlider("directional.cascadeFade", d.cascadeFade);
    changed |= fieldCombo("directional.cascadeBlend", d.cascadeBlend);
    changed |= fieldCombo("directional.projection", d.projection);
    if (d.projection == shadows::CascadeProjection::DepthFit) {
        changed |= fieldSlider("directional.depthFitSteps", d.depthFitSteps);
        changed |= fieldSlider("directional.depthFitHysteresis", d.depthFitHysteresis);
    }
    changed |= fieldLogSlider("directional.depthBias", d.depthBias);
    ImGui::Separator();
    ImGui::TextUnformatted("spot and point lights");
    ImGui::PushID("local");
    shadows::LocalShadowSettings& o = s.local;
    changed |= fieldPowerOfTwo("local.atlasSize", o.atlasSize);
    changed |= atlasFormatCombo(o.atlasFormat);
    changed |= filterCombo("filter", o.filter);
    changed |= fieldCombo("local.pointMode", o.pointMode);
    changed |= fieldPowerOfTwo("local.cubeMapSize", o.cubeMapSize);
    changed |= fieldPowerOfTwo("local.tileResolution", o.tileResolution);
    changed |= fieldPowerOfTwo("local.minTileResolution", o.minTileResolution);
    changed |= fieldSlider("local.nearPlane", o.nearPlane);
    changed |= fieldLogSlider("local.depthBias", o.depthBias);
    changed |= fieldCombo("local.spotFovBias", o.spotFovBias);
    changed |= fieldCombo("local.clusterBuild", o.clusterBuild);
    ImGui::PopID();
    ImGui::Separator();
    ImGui::TextUnformatted("soft shadows (poisson, pcss)");
    changed |= softSettings(s.soft);
    ImGui::Separator();
    ImGui::TextUnformatted("static shadow maps");
    ImGui::PushID("static");
    shadows::StaticShadowSettings& m = s.staticMaps;
    changed |= fieldCombo("static.update", m.update);
    changed |= fieldCombo("static.realtimeCasters", m.realtimeCasters);
    changed |= fieldPowerOfTwo("static.directionalAtlasSize", m.directionalAtlasSize);
    changed |= fieldPowerOfTwo("static.localAtlasSize", m.localAtlasSize);
    ImGui::PopID();
    ImGui::Separator();
    ImGui::TextUnformatted("contact shadows");
    shadows::ContactShadowSettings& c = s.contact;
    changed |= fieldCombo("contact.shadows", c.shadows);
    if (c.shadows == shadows::Toggle::On) {
        changed |= fieldSlider("contact.length", c.length);
        changed |= fieldSlider("contact.steps", c.steps);
        changed |= fieldSlider("contact.thickness", c.thickness);
        changed |= fieldSlider("contact.localLights", c.localLights);
    }
    return changed;
}

// Colour, intensity, shadow strength and biases: what every light kind has.
template <typename Light>
bool commonLightSettings(Light& light)
{
    bool changed = false;
    changed |= ImGui::ColorEdit3("colour", &light.color.x);
    changed |= ImGui::DragFloat("intensity", &light.intensity, 0.01f, 0.0f, 100.0f);
    changed |= ImGui::SliderFloat("shadow strength", &light.shadowStrength, 0.0f, 1.0f);
    changed |= ImGui::DragFloat("slope-scale bias", &light.slopeScaleBias, 0.01f, 0.0f, 10.0f);
    changed |= ImGui::DragFloat("normal bias", &light.normalBias, 0.01f, 0.0f, 10.0f);
    changed |= enumCombo("normal bias side", light.normalBiasSide, std::array{"receiver", "caster"});
    changed |= lightFilterCombo(light.shadowFilter);
    changed |= optionalEnumCombo("static map", light.shadowUpdate,
                                 std::array{"settings'", "every frame (none)", "on change", "on demand"});
    return changed;
}

// A spot or point light's own shadow resolution (texels per side its tile asks for when its reach fills the screen),
// or none of its own: the settings' local.tileResolution.
bool shadowResolutionSetting(std::optional<float>& resolution, std::uint32_t settingsResolution)
{
    bool own = resolution.has_value();
    bool changed = ImGui::Checkbox("own shadow resolution", &own);
    if (changed)
        resolution = own ? std::optional<float>(static_cast<float>(settingsResolution)) : std::nullopt;
    if (resolution)
        changed |= ImGui::SliderFloat("shadow resolution", &*resolution, scene::kMinShadowResolution,
                                      scene::kMaxShadowResolution, "%.0f", ImGuiSliderFlags_Logarithmic);
    return changed;
}

// Whether a static map is drawn on demand: the settings' mode, or a light's own.
bool anyOnDemand(const ViewState& state)
{
    const auto onDemand = [](const auto& lights) {
        return std::any_of(lights.begin(), lights.end(),
                           [](const auto& l) { return l.shadowUpdate == shadows::StaticShadowUpdate::OnDemand; });
    };
    return state.shadows.staticMaps.update == shadows::StaticShadowUpdate::OnDemand || onDemand(state.lights) ||
           onDemand(state.spotLights) || onDemand(state.pointLights);
}

bool spotLightSettings(scene::SpotLight& light, std::size_t index, std::uint32_t tileResolution)
{
    bool changed = false;
    ImGui::PushID(int(1000 + index));
    if (ImGui::TreeNodeEx(fmt::format("spot light {}: {}", index, light.name).c_str())) {
        changed |= commonLightSettings(light);
        changed |= ImGui::DragFloat3("position", &light.position.x, 0.05f);
        changed |= ImGui::DragFloat3("direction", &light.direction.x, 0.01f, -1.0f, 1.0f);
        changed |= ImGui::DragFloat("range", &light.range, 0.05f, 0.01f, 1000.0f);
        changed |= ImGui::SliderAngle("inner angle", &light.innerAngle, 0.0f, 89.0f);
        changed |= ImGui::SliderAngle("outer angle", &light.outerAngle, 0.0f, 89.0f);
        changed |= ImGui::DragFloat("source radius", &light.sourceRadius, 0.005f, 0.0f, light.range);
        changed |= shadowResolutionSetting(light.shadowResolution, tileResolution);
        ImGui::TreePop();
    }
    ImGui::PopID();
    return changed;
}

bool pointLightSettings(scene::PointLight& light, std::size_t index, std::uint32_t tileResolution)
{
    bool changed = false;
    ImGui::PushID(int(2000 + index));
    if (ImGui::TreeNodeEx(fmt::format("point light {}: {}", index, light.name).c_str())) {
        changed |= commonLightSettings(light);
        changed |= ImGui::DragFloat3("position", &light.position.x, 0.05f);
        changed |= ImGui::DragFloat("range", &light.range, 0.05f, 0.01f, 1000.0f);
        changed |= ImGui::DragFloat("source radius", &light.sourceRadius, 0.005f, 0.0f, light.range);
        changed |= shadowResolutionSetting(light.shadowResolution, tileResolution);
        ImGui::TreePop();
    }
    ImGui::PopID();
    return changed;
}

bool lightSettings(scene::DirectionalLight& light, std::size_t index)
{
    bool changed = false;
    ImGui::PushID(int(index));
    if (ImGui::TreeNodeEx(fmt::format("light {}: {}", index, light.name).c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= commonLightSettings(light);
        changed |= ImGui::DragFloat3("direction", &light.direction.x, 0.01f, -1.0f, 1.0f);
        changed |= ImGui::DragFloat("near plane offset", &light.nearPlaneOffset, 0.01f, 0.0f, 100.0f);
        changed |= ImGui::SliderFloat("angular diameter", &light.angularDiameter, 0.0f, scene::kMaxAngularDiameter,
                                      "%.2f deg");
        ImGui::TreePop();
    }
    ImGui::PopID();
    return changed;
}

bool objectSettings(std::vector<ObjectShadowState>& objects, const scene::Scene& scene)
{
    constexpr std::array kCastingNames{"on", "off", "two-sided", "shadows only"};
    bool changed = false;
    ImGuiListClipper clipper;
    clipper.Begin(int(std::min(objects.size(), scene.objects.size())));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            ImGui::PushID(int(3000 + i));
            ObjectShadowState& object = objects[std::size_t(i)];
            ImGui::SetNextItemWidth(110.0f);
            changed |= enumCombo("##cast", object.cast, kCastingNames);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("receive", &object.receive);
            ImGui::SameLine();
            bool dynamic = object.mobility == scene::Mobility::Dynamic;
            if (ImGui::Checkbox("dynamic", &dynamic)) {
                object.mobility = dynamic ? scene::Mobility::Dynamic : scene::Mobility::Static;
                changed = true;
            }
            ImGui::SameLine();
            ImGui::TextUnformatted(scene.objects[std::size_t(i)].name.c_str());
            ImGui::PopID();
        }
    return changed;
}

// One radio button per sample count of the msaa field that the device offers the lit pass.
bool msaaChoice(std::uint32_t& msaa, std::uint32_t offered)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt("msaa");
    bool changed = false;
    ImGui::TextUnformatted("MSAA");
    for (const double listed : field.listed) {
        const auto count = static_cast<std::uint32_t>(listed);
        if ((offered & count) == 0)
            continue;
        ImGui::SameLine();
        int value = int(msaa);
        if (ImGui::RadioButton(count == 1 ? "off" : fmt::format("{}x", count).c_str(), &value, int(count))) {
            msaa = count;
            changed = true;
        }
    }
    summaryTooltip(field);
    return changed;
}

// The shadowPath field's names (render::FrameDesc::shadowPath), a radio button each.
bool shadowPathChoice(render::ShadowPath& path)
{
    const settings::SettingsFieldInfo& field = settingsFieldAt("shadowPath");
    ImGui::TextUnformatted("directional shadows");
    int value = static_cast<int>(path);
    bool changed = false;
    for (const settings::SettingName& entry : field.names) {
        ImGui::SameLine();
        if (ImGui::RadioButton(std::string(entry.name).c_str(), &value, entry.value)) {
            path = static_cast<render::ShadowPath>(entry.value);
            changed = true;
        }
    }
    summaryTooltip(field);
    return changed;
}

void statusLines(const PanelStatus& status)
{
    ImGui::Text("frame %.1f ms", status.frameMs);
    // The frame graph's passes as they ran, with their GPU times.
    for (const render::PassTiming& pass : status.stats.passes)
        if (pass.gpuMs)
            ImGui::Text("%s %.2f ms", pass.name.c_str(), *pass.gpuMs);
        else
            ImGui::Text("%s", pass.name.c_str());
    ImGui::Text("caster draws %u, spot and point %u", status.stats.casterDraws, status.stats.localCasterDraws);
    for (const std::string& note : status.notes)
        ImGui::TextWrapped("%s", note.c_str());
    if (!status.error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "not applied: %s", status.error.c_str());
}

} // namespace

bool drawSettingsPanel(ViewState& state, const PanelStatus& status, const scene::Scene& scene)
{
    bool changed = false;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360.0f, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Penumbra");
    statusLines(status);
    changed |= ImGui::Checkbox("cascade view", &state.cascadeView);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("atlas overlay", &state.atlasOverlay);
    changed |= fieldSlider("anisotropy", state.maxAnisotropy);
    changed |= msaaChoice(state.msaa, status.msaaCounts);
    changed |= shadowPathChoice(state.shadowPath);
    if (state.hasEnvironment) {
        ImGui::TextUnformatted("environment");
        changed |= fieldLogSlider("environment.intensity", state.environmentIntensity, "%.2f");
        changed |= fieldSlider("environment.rotation", state.environmentRotation);
    }
    if (ImGui::CollapsingHeader("shadows", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= shadowSettings(state.shadows);
        if (anyOnDemand(state) && ImGui::Button("redraw static maps")) {
            state.redrawStaticMaps = true;
            changed = true;
        }
    }
    if (ImGui::CollapsingHeader("lights")) {
        for (std::size_t i = 0; i < state.lights.size(); ++i)
            changed |= lightSettings(state.lights[i], i);
        for (std::size_t i = 0; i < state.spotLights.size(); ++i)
            changed |= spotLightSettings(state.spotLights[i], i, state.shadows.local.tileResolution);
        for (std::size_t i = 0; i < state.pointLights.size(); ++i)
            changed |= pointLightSettings(state.pointLights[i], i, state.shadows.local.tileResolution);
    }
    if (ImGui::CollapsingHeader("objects: cast and receive shadows, dynamic"))
        changed |= objectSettings(state.objects, scene);
    ImGui::End();

    if (state.atlasOverlay && status.atlasPicture) {
        ImGui::SetNextWindowPos(ImVec2(380.0f, 10.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(300.0f, 320.0f), ImGuiCond_FirstUseEver);
        ImGui::Begin("shadow atlas");
        const float side = ImGui::GetContentRegionAvail().x > 64.0f ? ImGui::GetContentRegionAvail().x : 256.0f;
        ImGui::Image(const_cast<rhi::Texture*>(status.atlasPicture), ImVec2(side, side));
        ImGui::End();
    }
    return changed;
}

void drawAnimationPanel(AnimationPlayer& player, const scene::Rig& rig)
{
    if (rig.animations.empty())
        return;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 520.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360.0f, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("animation");
    std::vector<std::string> names;
    for (std::size_t a = 0; a < rig.animations.size(); ++a)
        names.push_back(fmt::format("{} '{}' ({:.2f} s)", a, rig.animations[a].name, rig.animations[a].duration()));
    std::size_t index = player.animation;
    if (indexCombo("animation", index, names)) {
        player.animation = static_cast<std::uint32_t>(index);
        player.time = 0.0f;
    }
    ImGui::Checkbox("play (Space)", &player.playing);
    if (ImGui::SliderFloat("time (, and .)", &player.time, 0.0f, rig.animations[player.animation].duration(), "%.2f s"))
        player.playing = false;
    ImGui::TextUnformatted("[ and ] pick the previous and next animation");
    ImGui::End();
}

} // namespace penumbra::viewer
