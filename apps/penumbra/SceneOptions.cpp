#include "SceneOptions.hpp"

#include "CommandLineSpecs.hpp"
#include "EnvironmentOption.hpp"
#include "LightOption.hpp"
#include "LightOverrides.hpp"
#include "RenderSettings.hpp"
#include "SceneShadowDefaults.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/LocalLights.hpp"
#include "penumbra/scene/Posing.hpp"
#include "penumbra/scene/SceneDefaults.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <map>
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

// --ambient over `settings`: its parts are the ambient fields, which the settings table reads and checks as it does a
// settings file's. Throws rhi::Error naming the syntax, or the field and what it allows.
void applyAmbientOption(RenderSettings& settings, const std::string& text)
{
    const std::optional<AmbientFields> fields = ambientFields(text);
    if (!fields)
        throw rhi::Error(fmt::format("'{}' is not {}", text, kAmbientSyntax));
    try {
        applySettingsFieldValues(settings, {{"ambient.color", fields->color},
                                            {"ambient.intensity", fields->intensity},
                                            {"ambient.ground", fields->ground}});
    } catch (const rhi::Error& e) {
        throw rhi::Error(fmt::format("'{}' ({}): {}", text, kAmbientSyntax, e.what()));
    }
}

std::string validateCamera(const std::string& camera)
{
    if (camera.find(':') != std::string::npos && !parseLookAt(camera))
        return fmt::format("'{}' is not px,py,pz:tx,ty,tz (six numbers, position and target apart)", camera);
    return {};
}

} // namespace

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
        .add_option(
            "--time", options.time,
            "Pose a glTF file's skins, morph targets and nodes at this many seconds into --animation (keys "
            "clamped at both ends; skinned and morphed on the GPU, and on the CPU for truth); bench starts there and "
            "advances 1/60 s per frame")
        ->check(CLI::Range(0.0f, 1.0e6f));
    command.add_option("--animation", options.animation,
                       "The glTF animation --time plays, by name or index (default: the first)");
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
                    fmt::format("Add a light (repeatable): {}; e.g. point:0,3,0:12:5. The first one replaces "
                                "the default sun of a glTF file without lights (see --default-lights)",
                                kLightSyntax))
        ->check(CLI::Validator(
            [](std::string& s) {
                std::string error;
                return parseLightOption(s, &error) ? std::string() : error;
            },
            "LIGHT"));
    command
        .add_option("--default-lights", options.defaultLights,
                    "The default sun of a glTF file without lights (45 degrees up over the camera's left shoulder, "
                    "with shadows): auto (added unless --light adds one), on (kept beside --light), off (never)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
    command
        .add_option("--missing-textures", options.missingTextures,
                    "A glTF texture whose image file cannot be read: fail (stop, naming the image, its URI and the "
                    "path tried) or stand-in (draw the material with its factors alone, noted)")
        ->check(CLI::IsMember({"fail", "stand-in"}))
        ->capture_default_str();
    command
        .add_option("--ambient", options.ambient,
                    fmt::format("Ambient light: {} (linear; the third field makes a sky/ground hemisphere), e.g. "
                                "0.6,0.7,1:0.1:0.3,0.25,0.2; default 1,1,1:0.03",
                                kAmbientSyntax))
        ->check(CLI::Validator(
            [](std::string& s) {
                RenderSettings probe;
                try {
                    applyAmbientOption(probe, s);
                    return std::string();
                } catch (const rhi::Error& e) {
                    return std::string(e.what());
                }
            },
            "AMBIENT"));
    command
        .add_option("--normal-bias-side", options.normalBiasSide,
                    "Where every light's normal bias goes: receiver (shadow lookups move towards the light, the "
                    "default) or caster (the shadow pass moves casters away from it)")
        ->check(CLI::IsMember({"receiver", "caster"}));
    command
        .add_option("--settings", options.settings,
                    "Settings JSON file: the shadow settings and the render-level ones (ambient, environment, "
                    "anisotropy, msaa, shadowPath; docs/settings.md); the options here win over it")
        ->check(CLI::ExistingFile);
    command
        .add_option("--shadow-defaults", options.shadowDefaults,
                    fmt::format("Shadow settings without --settings: scene (the shadow distance reaches the scene's "
                                "farthest point seen from the camera; a directional atlas of {0}x{0}, {1}x{1} for spot "
                                "and point lights) or documents (the design documents' values: {2:g} m, atlases of "
                                "{3}x{3})",
                                kSceneAtlasSize, kSceneLocalAtlasSize, shadows::ShadowSettings{}.maxDistance,
                                shadows::DirectionalShadowSettings{}.atlasSize))
        ->check(CLI::IsMember({"scene", "documents"}))
        ->capture_default_str();
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
    command.add_option("--dynamic", options.dynamicObjects,
                       "Make the objects of this name dynamic (repeatable; a glTF mesh's primitives NAME/0, NAME/1 "
                       "follow NAME): they are drawn into the realtime shadows every frame, never into static maps");
    command.add_flag("--moving-cars", options.movingCars,
                     fmt::format("With --scene street: {} of its cars drive down the road ({} m/s, dynamic); `bench` "
                                 "moves them on each frame, so only the lights that see a car draw their shadow again",
                                 scenes::kStreetMovingCars, scenes::kStreetCarSpeed));
    command
        .add_option("--light-static-map", options.lightStaticMaps,
                    fmt::format("A light's own static map mode, over --static-maps and the settings' (repeatable): "
                                "NAME=MODE, MODE one of {} (settings: the settings' mode)",
                                scene::kLightShadowUpdateNames))
        ->check(CLI::Validator(
            [](std::string& s) {
                return isLightShadowUpdate(s) ? std::string()
                                              : fmt::format("'{}' is not NAME=MODE with MODE one of {}", s,
                                                            scene::kLightShadowUpdateNames);
            },
            "NAME=MODE"));
    command
        .add_option(
            "--light-shadow-resolution", options.lightShadowResolutions,
            fmt::format("A spot or point light's own shadow resolution, over the settings' local.tileResolution "
                        "(repeatable): NAME=N, N texels per side ({} to {}) that its tile asks for when its "
                        "reach fills the screen",
                        scene::kMinShadowResolution, scene::kMaxShadowResolution))
        ->check(CLI::Validator(
            [](std::string& s) {
                return isLightShadowResolution(s)
                           ? std::string()
                           : fmt::format("'{}' is not NAME=N with N texels from {} to {}", s,
                                         scene::kMinShadowResolution, scene::kMaxShadowResolution);
            },
            "NAME=N"));
    command
        .add_option(
            "--baked", options.baked,
            "Static shadow maps from this `penumbra bake` folder instead of drawing static casters into them; implies "
            "--realtime-casters dynamic (the realtime atlases take static casters' depth from a cache drawn when a "
            "tile's view changes, not every frame; `all` is refused). A bake that does not match the scene, its lights "
            "or settings is refused")
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

// --time and --animation: the scene posed by scene::poseScene.
void poseAt(scene::Scene& scene, const SceneOptions& options)
{
    if (scene.rig.animations.empty())
        throw rhi::Error(fmt::format("--time/--animation: the scene '{}' has no animations", options.scene));
    try {
        scene::poseScene(scene, scene::findAnimation(scene.rig, options.animation.empty() ? "0" : options.animation),
                         options.time.value_or(0.0f));
    } catch (const scene::SceneError& error) {
        throw rhi::Error(fmt::format("--animation '{}': {}", options.animation, error.what()));
    }
}

} // namespace

namespace {

// --camera px,py,pz:tx,ty,tz: the scene camera moved there, keeping its field of view and planes.
void placeCamera(scene::Camera& camera, const LookAt& lookAt)
{
    // Straight up or down, +y cannot be the up vector; -z then puts +z at the bottom of the picture.
    const float vertical = std::abs(glm::normalize(lookAt.target - lookAt.position).y);
    const glm::vec3 up = vertical > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const scene::Camera placed = scene::lookAt(lookAt.position, lookAt.target, camera.fovY, up);
    camera.position = placed.position;
    camera.forward = placed.forward;
    camera.up = placed.up;
}

// Progress on stderr while a glTF file loads, once it has taken over a second (a dozen 2048 x 2048 textures take
// several): the images decoded so far, at most every half second, and the time the load took.
class LoadProgress {
public:
    explicit LoadProgress(std::string file) : file_(std::move(file)) {}
    ~LoadProgress()
    {
        if (const double seconds = elapsed(); seconds > kQuietSeconds)
            fmt::print(stderr, "loaded {} in {:.1f} s\n", file_, seconds);
    }
    LoadProgress(const LoadProgress&) = delete;
    LoadProgress& operator=(const LoadProgress&) = delete;

    void images(std::size_t done, std::size_t total)
    {
        const double seconds = elapsed();
        if (seconds <= kQuietSeconds || (seconds - lastLine_ < kEverySeconds && done < total))
            return;
        lastLine_ = seconds;
        fmt::print(stderr, "loading {}: {} of {} images decoded, {:.1f} s\n", file_, done, total, seconds);
    }

private:
    static constexpr double kQuietSeconds = 1.0, kEverySeconds = 0.5;
    double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

    std::string file_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    double lastLine_ = 0.0;
};

float aspectOf(const std::string& size)
{
    const std::optional<Size> parsed = parseSize(size);
    return parsed ? float(parsed->width) / float(parsed->height) : 1.0f;
}

} // namespace

LoadedScene loadScene(const SceneOptions& options)
{
    LoadedScene loaded;
    const std::optional<LookAt> lookAt = parseLookAt(options.camera);
    bool defaultLights = false;
    if (isGltfPath(options.scene)) {
        gltf::GltfOptions gltfOptions{.aspect = aspectOf(options.size),
                                      .missingTextures = options.missingTextures == "stand-in"
                                                             ? gltf::MissingTextures::StandIn
                                                             : gltf::MissingTextures::Fail};
        if (!options.camera.empty() && !lookAt)
            gltfOptions.camera = options.camera;
        LoadProgress progress(options.scene);
        gltfOptions.imageProgress = [&progress](std::size_t done, std::size_t total) { progress.images(done, total); };
        gltf::GltfScene file;
        try {
            file = gltf::loadGltf(options.scene, gltfOptions);
        } catch (const gltf::GltfMissingImageError& error) {
            throw gltf::GltfError(
                fmt::format("{}; --missing-textures stand-in draws the model without it", error.what()));
        }
        loaded.scene = std::move(file.scene);
        loaded.notes = std::move(file.notes);
        defaultLights = file.defaultLights;
    } else {
        if (!options.camera.empty() && !lookAt)
            throw rhi::Error(fmt::format("--camera '{}': the built-in scene '{}' has no named cameras; give a position "
                                         "and a target as px,py,pz:tx,ty,tz",
                                         options.camera, options.scene));
        loaded.scene = namedScene(options.scene);
    }
    if (options.time || !options.animation.empty())
        poseAt(loaded.scene, options);
    if (lookAt)
        placeCamera(loaded.scene.camera, *lookAt);
    if (defaultLights) {
        // The loader's sun faces the file's camera; the one used may be --camera's.
        loaded.scene.lights.clear();
        const bool keep = options.defaultLights == "on" || (options.defaultLights == "auto" && options.lights.empty());
        if (keep)
            loaded.scene.lights.push_back(scene::defaultSun(loaded.scene.camera));
        else
            loaded.notes.push_back(options.defaultLights == "off" ? "--default-lights off: the default sun left out"
                                                                  : "--light replaces the default sun "
                                                                    "(--default-lights on keeps it)");
    }
    if (options.localLights)
        scene::keepFirstLocalLights(loaded.scene, *options.localLights);
    for (const std::string& light : options.lights)
        addLight(loaded.scene, parseLightOption(light).value());
    loaded.scene.validate();
    applyLightOverrides(loaded.scene, options.filter, options.lightSize, options.normalBiasSide);
    for (const std::string& spec : options.lightShadowResolutions)
        applyLightShadowResolution(loaded.scene, spec);
    for (const std::string& spec : options.lightStaticMaps)
        applyLightShadowUpdate(loaded.scene, spec);
    for (const std::string& name : options.dynamicObjects)
        makeDynamic(loaded.scene, name);
    if (options.movingCars) {
        if (options.scene != "street")
            throw rhi::Error(
                fmt::format("--moving-cars: only the street scene has moving cars, not '{}'", options.scene));
        scenes::driveStreetCars(loaded.scene, 0.0f);
    }
    return loaded;
}

void applyBake(const SceneOptions& options, shadows::ShadowSettings& shadows)
{
    if (options.baked.empty())
        return;
    const auto realtimeCasters = options.settingsFields.find("static.realtimeCasters");
    if (realtimeCasters != options.settingsFields.end() && realtimeCasters->second == "all")
        throw rhi::Error(fmt::format("--baked {} with --realtime-casters all: the bake holds the static casters' "
                                     "shadows, and `all` would draw those casters into the realtime atlases every "
                                     "frame again; leave --realtime-casters out (--baked implies dynamic)",
                                     options.baked));
    // A bake is static maps, kept as loaded; the realtime atlases take the static casters' depth from the tiles'
    // cache (drawn when a tile's view changes) rather than drawing them every frame.
    if (!shadows::hasStaticMaps(shadows))
        shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
    shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
}

render::FrameDesc frameDesc(const SceneOptions& options, const scene::Scene& scene)
{
    const std::optional<Size> size = parseSize(options.size);
    if (!size)
        throw rhi::Error(fmt::format("--size '{}' is not WIDTHxHEIGHT", options.size));
    RenderSettings settings;
    bool ambientGiven = !options.ambient.empty();
    if (options.settings.empty() && options.shadowDefaults == "scene")
        settings.shadows = sceneShadowSettings(scene);
    if (!options.settings.empty())
        for (const std::string_view path : loadRenderSettings(options.settings, settings))
            ambientGiven = ambientGiven || path.starts_with("ambient.");
    if (!options.ambient.empty())
        applyAmbientOption(settings, options.ambient);
    applySettingsFieldValues(settings, options.settingsFields);
    applyBake(options, settings.shadows);
    render::FrameDesc frame;
    frame.width = size->width;
    frame.height = size->height;
    frame.depthPrepass = options.prepass == "on";
    frame.instancedDraws = options.instancing == "on";
    frame.shadows = settings.shadows;
    frame.ambient = settings.ambient;
    frame.maxAnisotropy = settings.anisotropy;
    frame.msaa = settings.msaa;
    frame.shadowPath = settings.shadowPath;
    const bool environmentFlag = options.settingsFields.contains("environment.source");
    frame.environment =
        environmentOf(settings.environment.source, isGltfPath(options.scene) && !ambientGiven,
                      settings.environment.intensity, settings.environment.rotation,
                      environmentFlag ? "--environment" : fmt::format("{}: environment.source", options.settings));
    return frame;
}

namespace {

// "  lights: 80 with shadows, 1 without; local atlas 75% used (fragmentation 0.00), 0 lights at a lowered resolution;
// local shadow tiles: 96 drawn, 0 cached (80 lights: its tile is new)".
void printLocalShadowCache(const render::FrameStats& s)
{
    fmt::print("  lights: {} with shadows, {} without", s.shadowedLights, s.lightsWithoutShadow);
    if (s.localAtlasUsed > 0.0f)
        fmt::print("; local atlas {:.0f}% used (fragmentation {:.2f}), {} lights at a lowered resolution",
                   100.0 * s.localAtlasUsed, s.localAtlasFragmentation, s.localLightsLowered);
    if (s.localTilesDrawn + s.localTilesCached != 0) {
        fmt::print("; local shadow tiles: {} drawn, {} cached", s.localTilesDrawn, s.localTilesCached);
        // Each update reads "spot light 3 ('lamp'): why"; the reasons counted.
        std::map<std::string, std::uint32_t> reasons;
        for (const std::string& update : s.localShadowUpdates)
            ++reasons[update.substr(update.rfind(": ") + 2)];
        for (const auto& [reason, lights] : reasons)
            fmt::print(" ({} lights: {})", lights, reason);
    }
    fmt::print("\n");
}

} // namespace

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
    printLocalShadowCache(s);
    if (s.environmentPrefilterMs)
        fmt::print("  environment prefiltered in {:.1f} ms (CPU and GPU, once per environment)\n",
                   *s.environmentPrefilterMs);
    if (!pictures.texelsPerMetre.empty()) {
        fmt::print("  directional shadow texels per metre at view depth");
        for (std::size_t i = 0; i < pictures.texelsPerMetre.size(); ++i)
            fmt::print(" {:g} m: {:.1f}{}", kTexelDensityDepths[i], pictures.texelsPerMetre[i],
                       i + 1 < pictures.texelsPerMetre.size() ? "," : "\n");
    }
    if (pictures.texelsOnScreen)
        fmt::print("  shadow texels per metre on screen: median {:.1f}, 10th percentile {:.1f}\n",
                   pictures.texelsOnScreen->median, pictures.texelsOnScreen->tenthPercentile);
    for (const std::string& note : pictures.notes)
        fmt::print("  note: {}\n", note);
}

} // namespace penumbra::apps
