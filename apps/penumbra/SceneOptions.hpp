#pragma once

#include "SettingsFieldOptions.hpp"
#include "ShadowScene.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::apps {

// What to render, shared by `render`, `parity`, `truth` and `bench --scene`: --scene, --lights, --camera, --light,
// --default-lights, --missing-textures, --ambient, --normal-bias-side, --settings, --size, --prepass, --instancing,
// --filter, --light-size, --dynamic, --moving-cars, --light-static-map, --baked, --time, --animation, and the settings
// fields' own options (addSettingsFieldOptions: --environment, --anisotropy, --msaa, --shadow-path, --projection,
// --static-maps, ...).
struct SceneOptions {
    std::string scene = "test";
    std::optional<std::uint32_t> localLights; // --lights N: the scene's first N local lights (keepFirstLocalLights)
    std::string camera; // empty: the scene's own
    std::vector<std::string> lights; // LightOption syntax, added to the scene's lights
    // A glTF file without lights gets a default sun: "auto" without --light, "on" with --light too, "off" never.
    std::string defaultLights = "auto";
    std::string missingTextures = "fail"; // a glTF texture whose image cannot be read: "fail" or "stand-in"
    std::string ambient; // kAmbientSyntax; empty: the settings file's, or render::AmbientLight's default
    std::string normalBiasSide; // "receiver" or "caster" for every light; empty: each light's own
    std::string settings;
    // Without --settings: "scene" fits the shadow distance to the scene and takes kSceneAtlasSize atlases
    // (sceneShadowSettings), "documents" keeps shadows::ShadowSettings{} (the design documents' values).
    std::string shadowDefaults = "scene";
    std::string size = "1280x720";
    std::string prepass = "on"; // render::FrameDesc::depthPrepass
    std::string instancing = "on"; // render::FrameDesc::instancedDraws
    std::string filter; // shadows::filterFromCommandName; empty: each light's own
    std::optional<float> lightSize; // every light's source size; nullopt: each light's own
    std::vector<std::string> dynamicObjects; // objects made dynamic (scene::Mobility), by name
    // --moving-cars: the street's ten moving cars (scenes::driveStreetCars) in their lanes, dynamic; `bench` drives
    // them on by 1/60 s each frame.
    bool movingCars = false;
    std::vector<std::string> lightStaticMaps; // NAME=MODE: a light's own static map mode (applyLightShadowUpdate)
    std::vector<std::string>
        lightShadowResolutions; // NAME=N: a light's own shadow tile size (applyLightShadowResolution)
    SettingsFieldValues settingsFields; // settings fields given by their options; the rest: the file's
    std::string baked; // a `penumbra bake` folder: static maps from it; empty: none
    std::optional<float> time; // seconds into the animation (scene::poseScene); empty: the rest pose
    std::string animation; // a glTF animation's name or index; empty: the first, when --time is given
};

// --filter's check, for every command that takes it: a shadows::filterFromCommandName name.
CLI::Validator filterValidator();

// Adds the options with validators that reject bad values before anything renders.
void addSceneOptions(CLI::App& command, SceneOptions& options);

struct LoadedScene {
    scene::Scene scene;
    std::vector<std::string> notes; // from the glTF loader
};

// The built-in scene or glTF file posed at --time in --animation, with --camera, --light (and the default sun of a
// glTF file without lights, placed for the camera used), --normal-bias-side and --dynamic applied. Throws
// scene::SceneError (a glTF file's errors name it) or rhi::Error.
LoadedScene loadScene(const SceneOptions& options);

// --baked's folder read (shadows::readStaticShadowBake), or nullopt without --baked.
std::optional<shadows::StaticShadowBake> loadBake(const SceneOptions& options);

// --baked's shadow settings: static maps kept (onChange unless the settings keep them otherwise) and
// RealtimeCasters::Dynamic, so the bake's casters are not drawn into the realtime atlases every frame; throws
// rhi::Error for --realtime-casters all with --baked.
void applyBake(const SceneOptions& options, shadows::ShadowSettings& shadows);

// Size, shadow settings, ambient light, environment, anisotropy, MSAA and shadow path of the frame (--ambient and the
// settings fields' options over the settings file's fields); throws rhi::Error naming the settings file and field.
// Without a settings file the shadows follow --shadow-defaults: sceneShadowSettings(scene) or the documents'.
render::FrameDesc frameDesc(const SceneOptions& options, const scene::Scene& scene);

// One line per rendered configuration: size, lights, caster draws and the GPU time of each pass;
// then the renderer's notes.
void printStats(const ShadowPictures& pictures, const scene::Scene& scene);

} // namespace penumbra::apps
