#include "SceneOptions.hpp"

#include "CommandLineSpecs.hpp"
#include "LightOption.hpp"
#include "LightOverrides.hpp"
#include "RenderSettings.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/LocalLights.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/geometric.hpp>
#include <optional>

namespace penumbra::apps {
namespace {

bool isGltfPath(const std::string& scene)
{
    const std::string extension = std::filesystem::path(scene).extension().string();
    return extension == ".gltf" || extension == ".glb";
}

std::string validateScene(const std::string& scene)
{
    if (isGltfPath(scene))
        return std::filesystem::is_regular_file(scene) ? std::string() : fmt::format("no such file: {}", scene);
    if (isNamedScene(scene))
        return {};
    return fmt::format("'{}' is neither a built-in scene ({}) nor a .gltf or .glb file", scene, kSceneNames);
}

std::string validateCamera(const std::string& camera)
{
    if (camera.find(':') != std::string::npos && !parseLookAt(camera))
        return fmt::format("'{}' is not px,py,pz:tx,ty,tz (six numbers, position and target apart)", camera);
    return {};
}

} // namespace

CLI::Validator anisotropyValidator()
{
    return CLI::Validator(
        [](std::string& s) {
            float value = 0.0f;
            const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
            return error == std::errc() && end == s.data() + s.size() && value >= 1.0f && value <= kMaxAnisotropyOption
                       ? std::string()
                       : fmt::format("'{}' is not a number from 1 (off) to {}", s, kMaxAnisotropyOption);
        },
        "N");
}

CLI::Validator msaaValidator()
{
    return CLI::Validator(
        [](std::string& s) {
            for (std::uint32_t count : kMsaaCounts)
                if (s == std::to_string(count))
                    return std::string();
            return fmt::format("'{}' is not a sample count: 1 (off), 2, 4 or 8", s);
        },
        "1|2|4|8");
}

CLI::Validator shadowPathValidator()
{
    return CLI::Validator(
        [](std::string& s) {
            return parseShadowPath(s)
                       ? std::string()
                       : fmt::format("'{}' is not a shadow path: {}", s, fmt::join(kShadowPathNames, ", "));
        },
        "PATH");
}

std::string shadowPathHelp()
{
    return "Where directional shadows are evaluated: forward (in the lit pass) or screenSpace (collected after the "
           "depth prepass by one full-screen pass into a screen-space shadow texture that the lit pass reads; needs "
           "--prepass on); default: the settings file's shadowPath, or forward";
}

CLI::Validator filterValidator()
{
    return CLI::Validator(
        [](std::string& s) {
            return shadows::filterFromCommandName(s)
                       ? std::string()
                       : fmt::format("'{}' is not one of {}", s, shadows::filterCommandNames());
        },
        "FILTER");
}

void addSceneOptions(CLI::App& command, SceneOptions& options)
{
    command
        .add_option("--scene", options.scene, fmt::format("A built-in scene ({}) or a .gltf or .glb file", kSceneNames))
        ->check(CLI::Validator([](std::string& s) { return validateScene(s); }, "SCENE"))
        ->capture_default_str();
    command.add_option("--lights", options.localLights,
                       "Keep the scene's first N local lights (its spot lights, then its point lights) and remove the "
                       "rest; lights added with --light stay");
    command
        .add_option("--camera", options.camera,
                    "A glTF camera (by camera or node name), or a position and a target as px,py,pz:tx,ty,tz "
                    "(e.g. 0,8,-20:0,0,5), which keeps the scene camera's field of view and planes")
        ->check(CLI::Validator([](std::string& s) { return validateCamera(s); }, "CAMERA"));
    command
        .add_option("--light", options.lights,
                    fmt::format("Add a light (repeatable): {}; e.g. point:0,3,0:12:5", kLightSyntax))
        ->check(CLI::Validator(
            [](std::string& s) {
                return parseLightOption(s) ? std::string() : fmt::format("'{}' is not {}", s, kLightSyntax);
            },
            "LIGHT"));
    command
        .add_option("--ambient", options.ambient,
                    fmt::format("Ambient light: {} (linear; the third field makes a sky/ground hemisphere), e.g. "
                                "0.6,0.7,1:0.1:0.3,0.25,0.2; default 1,1,1:0.03",
                                kAmbientSyntax))
        ->check(CLI::Validator(
            [](std::string& s) {
                return parseAmbientOption(s) ? std::string()
                                             : fmt::format("'{}' is not {} with colours of at least 0 and an intensity "
                                                           "of 0 to {}",
                                                           s, kAmbientSyntax, render::kMaxAmbientIntensity);
            },
            "AMBIENT"));
    command
        .add_option("--anisotropy", options.anisotropy,
                    fmt::format("Most anisotropic filtering of textures, 1 (off) to {}; more than the device allows is "
                                "lowered to its limit and noted; default {}",
                                kMaxAnisotropyOption, render::FrameDesc{}.maxAnisotropy))
        ->check(anisotropyValidator());
    command
        .add_option("--normal-bias-side", options.normalBiasSide,
                    "Where every light's normal bias goes: receiver (shadow lookups move towards the light, the "
                    "default) or caster (the shadow pass moves casters away from it)")
        ->check(CLI::IsMember({"receiver", "caster"}));
    command
        .add_option("--settings", options.settings,
                    "Shadow settings JSON file, with optional \"ambient\" object and \"anisotropy\" number")
        ->check(CLI::ExistingFile);
    command
        .add_option("--filter", options.filter,
                    fmt::format("Every light's shadow filter, over the settings' and the lights' own: {}",
                                shadows::filterCommandNames()))
        ->check(filterValidator());
    addSettingsFieldOptions(command, options.settingsFields);
    command
        .add_option("--light-size", options.lightSize,
                    fmt::format("Every light's source size for soft shadows: degrees of angular diameter for "
                                "directional lights (0 to {}), world units of radius for spot and point lights (0 to "
                                "their range)",
                                scene::kMaxAngularDiameter))
        ->check(CLI::NonNegativeNumber);
    command.add_option("--size", options.size, "Picture size as WIDTHxHEIGHT, each 1 to 8192")
        ->check(CLI::Validator(
            [](std::string& s) {
                return parseSize(s) ? std::string()
                                    : fmt::format("'{}' is not WIDTHxHEIGHT with each 1 to {}", s, kMaxSize);
            },
            "WxH"))
        ->capture_default_str();
    command
        .add_option("--prepass", options.prepass,
                    "on: draw opaque and alpha-tested geometry depth-only first, then shade each visible pixel once "
                    "(equal depth test); off: the lit pass alone")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    command
        .add_option("--instancing", options.instancing,
                    "on: objects that share a mesh and material are drawn as the instances of one draw in every pass; "
                    "off: a draw per object (the same picture)")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    command
        .add_option("--msaa", options.msaa,
                    "Samples per pixel of the lit pass: 1 (off), 2, 4 or 8, as the device offers them; default 1")
        ->check(msaaValidator());
    command.add_option("--shadow-path", options.shadowPath, shadowPathHelp())->check(shadowPathValidator());
    command.add_option("--dynamic", options.dynamicObjects,
                       "Make the objects of this name dynamic (repeatable; a glTF mesh's primitives NAME/0, NAME/1 "
                       "follow NAME): they are drawn into the realtime shadows every frame, never into static maps");
    command
        .add_option("--light-static-map", options.lightStaticMaps,
                    fmt::format("A light's own static map mode, over --static-maps and the settings' (repeatable): "
                                "NAME=MODE, MODE one of {} (settings: the settings' mode)",
                                scene::kShadowUpdateNames))
        ->check(CLI::Validator(
            [](std::string& s) {
                return isLightShadowUpdate(s)
                           ? std::string()
                           : fmt::format("'{}' is not NAME=MODE with MODE one of {}", s, scene::kShadowUpdateNames);
            },
            "NAME=MODE"));
    command
        .add_option(
            "--baked", options.baked,
            "Static shadow maps from this `penumbra bake` folder instead of drawing static casters; a bake that "
            "does not match the scene, its lights or settings is refused")
        ->check(CLI::ExistingDirectory);
}

std::optional<shadows::StaticShadowBake> loadBake(const SceneOptions& options)
{
    if (options.baked.empty())
        return std::nullopt;
    return shadows::readStaticShadowBake(options.baked);
}

namespace {

// --dynamic NAME: every object named NAME, or a primitive NAME/k of a glTF mesh.
void makeDynamic(scene::Scene& scene, const std::string& name)
{
    bool found = false;
    for (scene::Object& object : scene.objects)
        if (object.name == name || object.name.rfind(name + "/", 0) == 0) {
            object.mobility = scene::Mobility::Dynamic;
            found = true;
        }
    if (!found)
        throw rhi::Error(fmt::format("--dynamic '{}': the scene has no object of that name", name));
}

} // namespace

LoadedScene loadScene(const SceneOptions& options)
{
    LoadedScene loaded;
    const std::optional<LookAt> lookAt = parseLookAt(options.camera);
    if (isGltfPath(options.scene)) {
        gltf::GltfOptions gltfOptions;
        if (!options.camera.empty() && !lookAt)
            gltfOptions.camera = options.camera;
        gltf::GltfScene file = gltf::loadGltf(options.scene, gltfOptions);
        loaded.scene = std::move(file.scene);
        loaded.notes = std::move(file.notes);
    } else {
        if (!options.camera.empty() && !lookAt)
            throw rhi::Error(fmt::format("--camera '{}': the built-in scene '{}' has no named cameras; give a position "
                                         "and a target as px,py,pz:tx,ty,tz",
                                         options.camera, options.scene));
        loaded.scene = namedScene(options.scene);
    }
    if (options.localLights)
        scene::keepFirstLocalLights(loaded.scene, *options.localLights);
    for (const std::string& light : options.lights)
        addLight(loaded.scene, parseLightOption(light).value());
    if (!options.lights.empty())
        loaded.scene.validate();
    applyLightOverrides(loaded.scene, options.filter, options.lightSize, options.normalBiasSide);
    for (const std::string& spec : options.lightStaticMaps)
        applyLightShadowUpdate(loaded.scene, spec);
    for (const std::string& name : options.dynamicObjects)
        makeDynamic(loaded.scene, name);
    if (lookAt) {
        scene::Camera& camera = loaded.scene.camera;
        // Straight up or down, +y cannot be the up vector; -z then puts +z at the bottom of the picture.
        const float vertical = std::abs(glm::normalize(lookAt->target - lookAt->position).y);
        const glm::vec3 up = vertical > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
        const scene::Camera placed = scene::lookAt(lookAt->position, lookAt->target, camera.fovY, up);
        camera.position = placed.position;
        camera.forward = placed.forward;
        camera.up = placed.up;
        loaded.scene.validate();
    }
    return loaded;
}

render::FrameDesc frameDesc(const SceneOptions& options)
{
    const std::optional<Size> size = parseSize(options.size);
    if (!size)
        throw rhi::Error(fmt::format("--size '{}' is not WIDTHxHEIGHT", options.size));
    render::FrameDesc frame;
    frame.width = size->width;
    frame.height = size->height;
    frame.depthPrepass = options.prepass == "on";
    frame.instancedDraws = options.instancing == "on";
    if (!options.settings.empty()) {
        RenderSettings settings = loadRenderSettings(options.settings);
        frame.shadows = settings.shadows;
        frame.ambient = settings.ambient.value_or(frame.ambient);
        frame.maxAnisotropy = settings.anisotropy.value_or(frame.maxAnisotropy);
        frame.msaa = settings.msaa.value_or(frame.msaa);
        frame.shadowPath = settings.shadowPath.value_or(frame.shadowPath);
    }
    if (!options.shadowPath.empty())
        frame.shadowPath = parseShadowPath(options.shadowPath).value();
    if (!options.ambient.empty())
        frame.ambient = parseAmbientOption(options.ambient).value();
    frame.maxAnisotropy = options.anisotropy.value_or(frame.maxAnisotropy);
    frame.msaa = options.msaa.value_or(frame.msaa);
    applySettingsFieldValues(frame.shadows, options.settingsFields);
    // A bake is static maps: kept as loaded.
    if (!options.baked.empty() && !shadows::hasStaticMaps(frame.shadows))
        frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
    return frame;
}

void printStats(const ShadowPictures& pictures, const scene::Scene& scene)
{
    const render::FrameStats& s = pictures.stats;
    fmt::print("{:<24} {}x{}, {} objects, lights: {} directional, {} spot, {} point; caster draws {} ({} without "
               "culling bias)",
               pictures.configuration, pictures.lit.width, pictures.lit.height, scene.objects.size(),
               scene.lights.size(), scene.spotLights.size(), scene.pointLights.size(), s.casterDraws,
               s.casterDrawsWithoutCullingBias);
    if (s.localCasterDraws != 0)
        fmt::print(", {} into spot and point shadows", s.localCasterDraws);
    for (std::size_t i = 0; i < s.passes.size(); ++i)
        if (s.passes[i].gpuMs)
            fmt::print("{} {} {:.2f} ms", i == 0 ? "; GPU:" : ",", s.passes[i].name, *s.passes[i].gpuMs);
    fmt::print("\n");
    if (!pictures.texelsPerMetre.empty()) {
        fmt::print("  directional shadow texels per metre at view depth");
        for (std::size_t i = 0; i < pictures.texelsPerMetre.size(); ++i)
            fmt::print(" {:g} m: {:.1f}{}", kTexelDensityDepths[i], pictures.texelsPerMetre[i],
                       i + 1 < pictures.texelsPerMetre.size() ? "," : "\n");
    }
    for (const std::string& note : pictures.notes)
        fmt::print("  note: {}\n", note);
}

} // namespace penumbra::apps
