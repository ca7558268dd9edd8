#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scene/Scene.hpp"

#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

// What the static shadow tests (StaticShadowsTest, StaticShadowParityTest) share: small frames and static atlases,
// a small scene of boxes under a sun and a spot light, and the picture comparison of the bound.
namespace penumbra::testing {

inline constexpr std::uint32_t kStaticWidth = 160;
inline constexpr std::uint32_t kStaticHeight = 90;

// Static maps kept (`update`) in static atlases of 1024 (directional) and 512 (spot and point) texels.
inline render::FrameDesc staticMapsFrame(shadows::StaticShadowUpdate update = shadows::StaticShadowUpdate::OnChange)
{
    render::FrameDesc frame;
    frame.width = kStaticWidth;
    frame.height = kStaticHeight;
    frame.shadows.staticMaps.update = update;
    frame.shadows.staticMaps.directionalAtlasSize = 1024;
    frame.shadows.staticMaps.localAtlasSize = 512;
    return frame;
}

// Ground, three boxes and a spot light over box "a"; the sun sees them all.
inline scene::Scene boxesUnderASpot()
{
    scene::Scene s;
    const std::uint32_t grey = s.addMaterial({.name = "grey", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    s.addObject("ground", s.addMesh(scene::makeBox({12.0f, 0.1f, 12.0f})), grey,
                glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    const std::uint32_t box = s.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f}));
    s.addObject("a", box, grey, glm::translate(glm::mat4(1.0f), {-3.0f, 0.5f, 0.0f}));
    s.addObject("b", box, grey, glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f}));
    s.addObject("c", box, grey, glm::translate(glm::mat4(1.0f), {6.0f, 0.5f, 3.0f}));
    s.lights = {{.name = "sun", .intensity = 1.5f, .direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f))}};
    s.spotLights = {{.name = "lamp",
                     .intensity = 40.0f,
                     .position = {-3.0f, 4.0f, 0.0f},
                     .direction = {0.0f, -1.0f, 0.0f},
                     .range = 8.0f,
                     .innerAngle = 0.4f,
                     .outerAngle = 0.5f}};
    s.camera = scene::lookAt({0.0f, 8.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, 0.9f);
    return s;
}

// Moves an object by `offset` in world space, its bounds with it.
inline void moveObject(scene::Scene& scene, const std::string& name, glm::vec3 offset)
{
    scene::Object& object = scene.objects.at(scene.findObject(name).value());
    object.transform = glm::translate(glm::mat4(1.0f), offset) * object.transform;
    object.worldBounds = scene.meshOf(object).bounds.transformed(object.transform);
    ++scene.revision;
}

} // namespace penumbra::testing
