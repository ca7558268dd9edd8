#pragma once

#include "penumbra/scene/Scene.hpp"

#include <filesystem>
#include <functional>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::gltf {

// A glTF file that cannot be read, or that refers to something it does not hold. what() starts
// with the file's path and names the element, e.g. "scene.gltf: mesh 2 ('Cube') primitive 0:
// accessor 5 (indices) refers to vertex 40 but POSITION has 24".
class GltfError : public scene::SceneError {
public:
    using scene::SceneError::SceneError;
};

// An image file that a texture uses and that cannot be read: what() names the image, its URI and the path tried.
class GltfMissingImageError : public GltfError {
public:
    using GltfError::GltfError;
};

// What loadGltf does with a texture whose image file cannot be read.
enum class MissingTextures {
    Fail, // throw GltfMissingImageError
    StandIn, // draw the material without the texture, with a note: its factors alone (no emissive light)
};

// Choices of loadGltf.
struct GltfOptions {
    // The camera to use: a glTF camera's name, or the name of a node that carries one. Without
    // it the first perspective camera met walking the scene's nodes is used.
    std::optional<std::string> camera;
    // The frame's width / height, for the framing camera of a file without one: it fits the scene's bounding sphere
    // to the narrower field of view.
    float aspect = 1.0f;
    MissingTextures missingTextures = MissingTextures::Fail;
    // Called after each image is decoded (images decode in parallel, one per hardware thread; this is called on one
    // thread at a time) with the images done and in all: for a progress line while a large file loads.
    std::function<void(std::size_t done, std::size_t total)> imageProgress;
};

// A loaded glTF file: the scene and the loader's notes.
struct GltfScene {
    penumbra::scene::Scene scene;
    // What was substituted or left out: defaults added, extensions and features ignored,
    // tinygltf's warnings. Nothing here changes whether the scene renders.
    std::vector<std::string> notes;
    // The file has no lights and scene.lights holds the default sun alone: a light the user adds replaces it.
    bool defaultLights = false;
};

// Loads a glTF 2.0 file (.gltf with external or data-URI buffers, or .glb) into a validated Scene:
// - every primitive of mode TRIANGLES becomes a mesh (POSITION, NORMAL, TEXCOORD_0 and _1, COLOR_0,
//   TANGENT, computed for normal textures without it; indices of 8, 16 or 32 bits or none). Missing normals are
//   computed flat, as glTF requires. Primitives are shared between the nodes that use them; a node with a mirroring
//   transform gets a copy with reversed winding (see Object).
// - the default scene's node hierarchy (matrix or translation/rotation/scale); nodes with a
//   singular transform (scale 0) are skipped.
// - materials (Material): factors and the five textures (decoded into Scene::textures, each image
//   once) with texCoord and KHR_texture_transform, normal scale, occlusion strength, emissive with
//   KHR_materials_emissive_strength, doubleSided, KHR_materials_unlit; alphaMode OPAQUE ->
//   CasterMode::On, MASK -> Clip with alphaCutoff, BLEND -> Dither and Material::blend.
// - per node, extras {"penumbra": {"castShadows": "on" | "off" | "twoSided" | "shadowsOnly",
//   "receiveShadows": bool}} set Object::castShadows and receiveShadows of its primitives; children
//   inherit what they do not set.
// - skins (JOINTS_n, WEIGHTS_n), morph targets (POSITION, NORMAL, TANGENT) and animations go into Scene::rig; the
//   scene is posed at rest (scene::poseScene with no animation), scene::poseScene poses it at another time.
// - what is left out (other extensions) is noted once per file.
// - KHR_lights_punctual: directional -> Scene::lights, spot -> spotLights (cone angles are
//   half-angles in both), point -> pointLights; lights shine along their node's -z. A light
//   without range gets kDefaultRangePerSqrtIntensity * sqrt(intensity) (at least 1): the distance
//   where intensity / d^2 falls to 1/256, an 8-bit step of a unit-intensity surface.
// - cameras: perspective, looking along the node's -z with +y up; aspectRatio is ignored (the
//   frame decides it); an infinite far plane ends beyond the scene's bounds.
// - no camera: framingCamera() of the scene's bounds; then, with no light, scene::defaultSun() of that camera.
// Before anything is read the file is checked as the Khronos glTF Validator checks it: the type, range and
// enum value of every property read, required properties, every index, the node hierarchy, the byte ranges
// of buffers, views and accessors, and the limits of gltf/src/GltfLimits.hpp and GltfImages.hpp (file,
// buffer and accessor sizes, object counts, node depth, picture sizes). A bad file's error names the JSON
// pointer of the offending value: "scene.gltf: /nodes/17/scale: expected an array of 3 numbers, got -1".
// A primitive without POSITION is skipped with a note; the deviations the validator reports but
// rendering does not depend on (accessor min/max, non-unit normals) are noted once per kind.
// Throws GltfError, and nothing else for a bad file; no partial scene is returned.
GltfScene loadGltf(const std::filesystem::path& path, const GltfOptions& options = {});

// The same for a file's bytes in memory: `name` is what errors call the file, external buffers and
// images are looked up in `folder`.
GltfScene loadGltf(std::span<const std::uint8_t> bytes, const std::string& name, const std::filesystem::path& folder,
                   const GltfOptions& options = {});

inline constexpr float kDefaultRangePerSqrtIntensity = 16.0f;

} // namespace penumbra::gltf
