#include "ViewState.hpp"

#include "penumbra/rhi/Format.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <imgui.h>
#include <utility>

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

// shadows::CascadeProjection's names, in its order.
std::array<const char*, shadows::kCascadeProjectionCount> projectionNames()
{
    std::array<const char*, shadows::kCascadeProjectionCount> names{};
    for (std::size_t i = 0; i < names.size(); ++i)
        names[i] = shadows::cascadeProjectionNames()[i].name.data();
    return names;
}

// A light's own filter: "atlas" (scene::kAtlasShadowFilter) or one of the filters.
bool lightFilterCombo(std::int32_t& filter)
{
    std::array<const char*, shadows::kShadowFilterCount + 1> names{"atlas"};
    for (std::size_t i = 0; i < shadows::kShadowFilterCount; ++i)
        names[i + 1] = filterNames()[i];
    int index = filter + 1;
    const bool changed = ImGui::Combo("shadow filter", &index, names.data(), int(names.size()));
    if (changed)
        filter = index - 1;
    return changed;
}

bool sampleCountCombo(const char* label, std::uint32_t& count)
{
    constexpr std::array names{"16", "32", "64"};
    int index = count == 64 ? 2 : count == 32 ? 1 : 0;
    const bool changed = ImGui::Combo(label, &index, names.data(), int(names.size()));
    if (changed)
        count = shadows::kPoissonSampleCounts[index];
    return changed;
}

bool softSettings(shadows::SoftShadowSettings& s)
{
    bool changed = false;
    changed |= ImGui::SliderFloat("blocker search scale", &s.blockerSearchScale, 0.1f, 10.0f);
    changed |= ImGui::SliderFloat("penumbra scale", &s.penumbraScale, 0.1f, 10.0f);
    changed |= sampleCountCombo("blocker samples", s.blockerSamples);
    changed |= sampleCountCombo("filter samples", s.filterSamples);
    changed |= ImGui::SliderFloat("min penumbra (texels)", &s.minPenumbraTexels, 0.0f, 64.0f);
    changed |= ImGui::SliderFloat("max penumbra (texels)", &s.maxPenumbraTexels, 0.0f, 64.0f);
    changed |= ImGui::SliderFloat("poisson radius (texels)", &s.poissonRadiusTexels, 0.5f, 64.0f);
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

// Ranges of the widgets are the settings' allowed ranges where those are simple; values typed in
// (ctrl+click) may leave them, and validation then reports the field.
bool shadowSettings(shadows::ShadowSettings& s)
{
    bool changed = false;
    changed |= ImGui::DragFloat("max distance", &s.maxDistance, 0.5f, 0.001f, 1000.0f);
    changed |= ImGui::SliderFloat("distance fade", &s.distanceFade, 0.001f, 1.0f);
    shadows::DirectionalShadowSettings& d = s.directional;
    changed |= ImGui::InputScalar("atlas size", ImGuiDataType_U32, &d.atlasSize);
    changed |= atlasFormatCombo(d.atlasFormat);
    changed |= filterCombo("filter", d.filter);
    int cascades = int(d.cascadeCount);
    if (ImGui::SliderInt("cascades", &cascades, 1, 4)) {
        d.cascadeCount = std::uint32_t(cascades);
        changed = true;
    }
    changed |= ImGui::SliderFloat3("cascade ratios", &d.cascadeRatios.x, 0.0f, 1.0f);
    changed |= ImGui::SliderFloat("cascade fade", &d.cascadeFade, 0.001f, 1.0f);
    changed |= enumCombo("cascade blend", d.cascadeBlend, std::array{"hard", "soft", "dither"});
    changed |= enumCombo("projection", d.projection, projectionNames());
    ImGui::Separator();
    ImGui::TextUnformatted("spot and point lights");
    ImGui::PushID("local");
    shadows::LocalShadowSettings& o = s.local;
    changed |= ImGui::InputScalar("atlas size", ImGuiDataType_U32, &o.atlasSize);
    changed |= atlasFormatCombo(o.atlasFormat);
    changed |= filterCombo("filter", o.filter);
    changed |= enumCombo("point lights", o.pointMode, std::array{"atlas tiles", "cube maps"});
    changed |= ImGui::InputScalar("cube map size", ImGuiDataType_U32, &o.cubeMapSize);
    ImGui::PopID();
    ImGui::Separator();
    ImGui::TextUnformatted("soft shadows (poisson, pcss)");
    changed |= softSettings(s.soft);
    ImGui::Separator();
    ImGui::TextUnformatted("static shadow maps");
    ImGui::PushID("static");
    shadows::StaticShadowSettings& m = s.staticMaps;
    changed |= enumCombo("update", m.update, std::array{"every frame (none)", "on change", "on demand"});
    changed |= enumCombo("realtime casters", m.realtimeCasters, std::array{"all", "dynamic"});
    changed |= ImGui::InputScalar("directional atlas size", ImGuiDataType_U32, &m.directionalAtlasSize);
    changed |= ImGui::InputScalar("local atlas size", ImGuiDataType_U32, &m.localAtlasSize);
    ImGui::PopID();
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
    changed |= enumCombo("static map", light.shadowUpdate,
                         std::array{"settings'", "every frame (none)", "on change", "on demand"});
    return changed;
}

// Whether a static map is drawn on demand: the settings' mode, or a light's own.
bool anyOnDemand(const ViewState& state)
{
    const auto onDemand = [](const auto& lights) {
        return std::any_of(lights.begin(), lights.end(),
                           [](const auto& l) { return l.shadowUpdate == scene::ShadowUpdate::OnDemand; });
    };
    return state.shadows.staticMaps.update == shadows::StaticShadowUpdate::OnDemand || onDemand(state.lights) ||
           onDemand(state.spotLights) || onDemand(state.pointLights);
}

bool spotLightSettings(scene::SpotLight& light, std::size_t index)
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
        ImGui::TreePop();
    }
    ImGui::PopID();
    return changed;
}

bool pointLightSettings(scene::PointLight& light, std::size_t index)
{
    bool changed = false;
    ImGui::PushID(int(2000 + index));
    if (ImGui::TreeNodeEx(fmt::format("point light {}: {}", index, light.name).c_str())) {
        changed |= commonLightSettings(light);
        changed |= ImGui::DragFloat3("position", &light.position.x, 0.05f);
        changed |= ImGui::DragFloat("range", &light.range, 0.05f, 0.01f, 1000.0f);
        changed |= ImGui::DragFloat("source radius", &light.sourceRadius, 0.005f, 0.0f, light.range);
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

// One radio button per sample count the device offers the lit pass.
bool msaaChoice(std::uint32_t& msaa, std::uint32_t offered)
{
    bool changed = false;
    ImGui::TextUnformatted("MSAA");
    for (std::uint32_t count = 1; count <= 8; count *= 2) {
        if ((offered & count) == 0)
            continue;
        ImGui::SameLine();
        int value = int(msaa);
        if (ImGui::RadioButton(count == 1 ? "off" : fmt::format("{}x", count).c_str(), &value, int(count))) {
            msaa = count;
            changed = true;
        }
    }
    return changed;
}

// Forward or screen-space directional shadows (render::FrameDesc::shadowPath).
bool shadowPathChoice(render::ShadowPath& path)
{
    ImGui::TextUnformatted("directional shadows");
    int value = static_cast<int>(path);
    bool changed = false;
    for (const auto& [choice, label] : {std::pair{render::ShadowPath::Forward, "forward"},
                                        std::pair{render::ShadowPath::ScreenSpace, "screen-space"}}) {
        ImGui::SameLine();
        if (ImGui::RadioButton(label, &value, static_cast<int>(choice))) {
            path = choice;
            changed = true;
        }
    }
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
    changed |= ImGui::SliderFloat("texture anisotropy", &state.maxAnisotropy, 1.0f, 16.0f, "%.0f");
    changed |= msaaChoice(state.msaa, status.msaaCounts);
    changed |= shadowPathChoice(state.shadowPath);
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
            changed |= spotLightSettings(state.spotLights[i], i);
        for (std::size_t i = 0; i < state.pointLights.size(); ++i)
            changed |= pointLightSettings(state.pointLights[i], i);
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

} // namespace penumbra::viewer
