#include "penumbra/scenes/TestScenes.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace penumbra::scenes {

scene::Scene makeContactScene()
{
    scene::Scene scene;
    const std::uint32_t ground = scene.addMaterial({.name = "ground", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    const std::uint32_t caster = scene.addMaterial({.name = "caster", .baseColor = {0.8f, 0.45f, 0.3f, 1.0f}});
    const auto addBox = [&](std::string name, glm::vec3 halfExtents, glm::vec3 centre, std::uint32_t material) {
        scene.addObject(std::move(name), scene.addMesh(scene::makeBox(halfExtents)), material,
                        glm::translate(glm::mat4(1.0f), centre));
    };
    addBox("ground", {10.0f, 0.1f, 10.0f}, {0.0f, -0.1f, 0.0f}, ground);
    addBox("pole", {kContactPoleHalfWidth, 0.5f * kContactPoleHeight, kContactPoleHalfWidth},
           {0.0f, 0.5f * kContactPoleHeight, 0.0f}, caster);
    addBox("slab", {0.6f, 0.05f, 0.6f}, {1.2f, 1.0f, -2.2f}, caster);
    for (int slat = 0; slat < 8; ++slat)
        addBox("fence " + std::to_string(slat + 1), {0.03f, 0.6f, 0.03f},
               {-1.2f + 0.3f * static_cast<float>(slat), 0.6f, 2.2f}, caster);
    // 45 degrees up, shining towards +x: the pole's point at height h shadows the ground at x = h.
    scene.lights = {{.name = "sun",
                     .intensity = 2.0f,
                     .direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)),
                     .angularDiameter = 10.0f}};
    scene.camera = scene::lookAt({1.4f, 7.0f, 0.0f}, {1.4f, 0.0f, 0.0f}, glm::radians(55.0f), {0.0f, 0.0f, -1.0f});
    return scene;
}

scene::Scene makeContactLocalLightsScene()
{
    scene::Scene scene = makeContactScene();
    scene.lights.clear();
    scene.spotLights.push_back({.name = "spot",
                                .intensity = 12.0f,
                                .position = {-2.5f, 3.0f, 0.5f},
                                .direction = glm::normalize(glm::vec3(3.0f, -3.0f, 0.5f)),
                                .range = 12.0f,
                                .innerAngle = glm::radians(40.0f),
                                .outerAngle = glm::radians(50.0f)});
    scene.pointLights.push_back({.name = "point", .intensity = 6.0f, .position = {-3.0f, 1.5f, -2.0f}, .range = 10.0f});
    scene.camera = scene::lookAt({4.0f, 2.0f, -1.0f}, {0.0f, 0.0f, 1.0f}, glm::radians(55.0f), {0.0f, 1.0f, 0.0f});
    return scene;
}

} // namespace penumbra::scenes
