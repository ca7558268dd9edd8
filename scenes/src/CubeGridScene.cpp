#include "penumbra/scenes/TestScenes.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace penumbra::scenes {

scene::Scene makeCubeGridScene(std::uint32_t count)
{
    scene::Scene scene;
    const std::uint32_t ground = scene.addMaterial({.name = "ground", .baseColor = {0.62f, 0.62f, 0.6f, 1.0f}});
    const std::uint32_t cubes = scene.addMaterial({.name = "cubes", .baseColor = {0.75f, 0.55f, 0.35f, 1.0f}});
    const auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    const float half = 0.5f * kCubeGridPitch * static_cast<float>(side);
    scene.addObject("ground", scene.addMesh(scene::makeBox({half + 2.0f, 0.1f, half + 2.0f})), ground,
                    glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    const std::uint32_t cube = scene.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f}));
    scene.objects.reserve(count + 1);
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 centre{-half + kCubeGridPitch * (static_cast<float>(i % side) + 0.5f), 0.5f,
                               -half + kCubeGridPitch * (static_cast<float>(i / side) + 0.5f)};
        scene.addObject("cube " + std::to_string(i + 1), cube, cubes, glm::translate(glm::mat4(1.0f), centre));
    }
    scene.lights = {{.name = "sun", .intensity = 2.5f, .direction = glm::normalize(glm::vec3(0.5f, -0.6f, -0.4f))}};
    // Low over the grid's south edge, looking across it: the cascades cover ever more cubes towards the horizon.
    scene.camera = scene::lookAt({0.0f, 3.0f, half + 4.0f}, {0.0f, 0.0f, half - 30.0f}, glm::radians(60.0f));
    return scene;
}

} // namespace penumbra::scenes
