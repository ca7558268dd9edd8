#include "penumbra/scenes/TestScenes.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace penumbra::scenes {

scene::Scene makeTownScene()
{
    scene::Scene scene;
    const std::uint32_t ground = scene.addMaterial({.name = "ground", .baseColor = {0.62f, 0.62f, 0.6f, 1.0f}});
    const std::uint32_t walls = scene.addMaterial({.name = "walls", .baseColor = {0.8f, 0.7f, 0.55f, 1.0f}});
    const std::uint32_t ball = scene.addMaterial({.name = "ball", .baseColor = {0.85f, 0.25f, 0.2f, 1.0f}});
    scene.addObject("ground", scene.addMesh(scene::makeBox({kTownHalfSize, 0.1f, kTownHalfSize})), ground,
                    glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    // Buildings 8 to 10 wide on a 25 metre grid, streets of 15 or more between them along x and z; heights vary by a
    // fixed pattern, so shadows of every length lie on the streets.
    constexpr int kBlocks = 8;
    constexpr float kPitch = 2.0f * kTownHalfSize / kBlocks;
    for (int row = 0; row < kBlocks; ++row)
        for (int column = 0; column < kBlocks; ++column) {
            const float height = 6.0f + 4.0f * static_cast<float>((row * 5 + column * 3) % 5);
            const glm::vec3 centre{-kTownHalfSize + kPitch * (static_cast<float>(column) + 0.5f), 0.5f * height,
                                   -kTownHalfSize + kPitch * (static_cast<float>(row) + 0.5f)};
            const float half = 0.5f * (kPitch - 12.0f) * (0.6f + 0.1f * static_cast<float>((row + column) % 3));
            scene.addObject("building " + std::to_string(row * kBlocks + column + 1),
                            scene.addMesh(scene::makeBox({half, 0.5f * height, half})), walls,
                            glm::translate(glm::mat4(1.0f), centre));
        }
    scene::Object& moving = scene.objects[scene.addObject("ball", scene.addMesh(scene::makeSphere(1.0f, 24, 12)), ball,
                                                          glm::translate(glm::mat4(1.0f), kTownBallStart))];
    moving.mobility = scene::Mobility::Dynamic;
    // Low in the west-south-west, so the buildings throw long shadows along the streets.
    scene.lights = {{.name = "sun", .intensity = 2.5f, .direction = glm::normalize(glm::vec3(0.75f, -0.5f, -0.35f))}};
    scene.camera = scene::lookAt({-20.0f, 30.0f, 125.0f}, {15.0f, 0.0f, 10.0f}, glm::radians(60.0f));
    scene.camera.farPlane = 400.0f;
    return scene;
}

} // namespace penumbra::scenes
