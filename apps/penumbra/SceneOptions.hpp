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
// --ambient,
// --anisotropy, --normal-bias-side, --settings, --size, --prepass, --instancing, --msaa, --shadow-path, --filter,
// --light-size, --dynamic, --light-static-map, --baked, and the shadow settings fields' own options
// (addSettingsFieldOptions: --projection, --static-maps, --realtime-casters).
struct SceneOptions {
    std::string scene = "test";
    std::optional<std::uint32_t> localLights; // --lights N: the scene's first N local lights (keepFirstLocalLights)
    std::string camera; // empty: the scene's own
    std::vector<std::string> lights; // LightOption syntax, added to the scene's lights
    std::string ambient; // kAmbientSyntax; empty: the settings file's, or render::AmbientLight's default
    std::optional<float> anisotropy; // empty: the settings file's, or FrameDesc's default
    std::string normalBiasSide; // "receiver" or "caster" for every light; empty: each light's own
    std::string settings;
    std::string size = "1280x720";
    std::string prepass = "on"; // render::FrameDesc::depthPrepass
    std::string instancing = "on"; // render::FrameDesc::instancedDraws
    std::optional<std::uint32_t> msaa; // render::FrameDesc::msaa; empty: the settings file's, or 1
    std::string shadowPath; // kShadowPathNames (render::FrameDesc::shadowPath); empty: the settings file's, or forward
    std::string filter; // shadows::filterFromCommandName; empty: each light's own
    std::optional<float> lightSize; // every light's source size; nullopt: each light's own
    std::vector<std::string> dynamicObjects; // objects made dynamic (scene::Mobility), by name
    std::vector<std::string> lightStaticMaps; // NAME=MODE: a light's own static map mode (applyLightShadowUpdate)
    SettingsFieldValues settingsFields; // shadow settings fields given by their options; the rest: the file's
    std::string baked; // a `penumbra bake` folder: static maps from it; empty: none
};

// --anisotropy's check, for every command that takes it: a number from 1 (off) to kMaxAnisotropyOption.
CLI::Validator anisotropyValidator();

// --msaa's check, for every command that takes it: a count of kMsaaCounts.
CLI::Validator msaaValidator();

// --shadow-path's check and help, for every command that takes it: one of kShadowPathNames.
CLI::Validator shadowPathValidator();
std::string shadowPathHelp();

// --filter's check, for every command that takes it: a shadows::filterFromCommandName name.
CLI::Validator filterValidator();

// Adds the options with validators that reject bad values before anything renders.
void addSceneOptions(CLI::App& command, SceneOptions& options);

struct LoadedScene {
    scene::Scene scene;
    std::vector<std::string> notes; // from the glTF loader
};

// The built-in scene or glTF file, with --camera, --light, --normal-bias-side and --dynamic applied. Throws
// scene::SceneError (a glTF file's errors name it) or rhi::Error.
LoadedScene loadScene(const SceneOptions& options);

// --baked's folder read (shadows::readStaticShadowBake), or nullopt without --baked.
std::optional<shadows::StaticShadowBake> loadBake(const SceneOptions& options);

// Size, shadow settings, ambient light, anisotropy, MSAA and shadow path of the frame (--ambient, --anisotropy, --msaa
// and --shadow-path over the settings file's "ambient", "anisotropy", "msaa" and "shadowPath"); throws
// rhi::Error naming the settings file and field.
render::FrameDesc frameDesc(const SceneOptions& options);

// One line per rendered configuration: size, lights, caster draws and the GPU time of each pass;
// then the renderer's notes.
void printStats(const ShadowPictures& pictures, const scene::Scene& scene);

} // namespace penumbra::apps
