#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scene/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace penumbra::testing {

// Many small lights over a grey ground seen from straight above (ManyLightsTest, ManyLightsParityTest): a grid of
// columns x rows, spot lights (pointing down) and point lights alternating, each lighting a pool about a world unit
// wide that no other light reaches; a dim moon; the camera high enough to see the grid in a 16:9 or square frame.
// Far beyond the 16 local lights the lit pass once drew.
inline constexpr std::uint32_t kManyLightsColumns = 20;
inline constexpr std::uint32_t kManyLightsRows = 15;
inline constexpr float kManyLightsPitch = 2.0f;

// Where light `i` of a grid of `columns` x `rows` (row by row) stands over the ground.
inline glm::vec3 manyLightsGroundPoint(std::uint32_t i, std::uint32_t columns, std::uint32_t rows)
{
    return {(static_cast<float>(i % columns) - 0.5f * float(columns - 1)) * kManyLightsPitch, 0.0f,
            (static_cast<float>(i / columns) - 0.5f * float(rows - 1)) * kManyLightsPitch};
}

// The lights in the lit pass's order (spot lights, then point lights), each with the ground point under it.
struct ManyLightsScene {
    scene::Scene scene;
    std::vector<glm::vec3> groundPoints; // per local light: spot lights first, then point lights
};

inline ManyLightsScene manyLightsScene(std::uint32_t columns = kManyLightsColumns, std::uint32_t rows = kManyLightsRows)
{
    ManyLightsScene result;
    scene::Scene& scene = result.scene;
    const std::uint32_t ground = scene.addMaterial({.name = "ground", .baseColor = {0.5f, 0.5f, 0.5f, 1.0f}});
    const glm::vec2 half = 0.5f * kManyLightsPitch * glm::vec2(float(columns), float(rows)) + 2.0f;
    scene.addObject("ground", scene.addMesh(scene::makeBox({half.x, 0.1f, half.y})), ground,
                    glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    std::vector<glm::vec3> spots, points;
    for (std::uint32_t i = 0; i < columns * rows; ++i) {
        const glm::vec3 under = manyLightsGroundPoint(i, columns, rows);
        // Hues around the circle, so that neighbours differ.
        const float hue = static_cast<float>(i % 7) / 7.0f;
        const glm::vec3 color{0.75f + 0.25f * std::cos(6.2832f * hue), 0.75f + 0.25f * std::cos(6.2832f * hue + 2.1f),
                              0.75f + 0.25f * std::cos(6.2832f * hue + 4.2f)};
        if (i % 2 == 0) {
            scene.spotLights.push_back({.name = "spot " + std::to_string(i),
                                        .color = color,
                                        .intensity = 4.0f,
                                        .position = under + glm::vec3(0.0f, 1.0f, 0.0f),
                                        .direction = {0.0f, -1.0f, 0.0f},
                                        .range = 2.0f,
                                        .innerAngle = 0.3f,
                                        .outerAngle = 0.6f});
            spots.push_back(under);
        } else {
            scene.pointLights.push_back({.name = "point " + std::to_string(i),
                                         .color = color,
                                         .intensity = 1.5f,
                                         .position = under + glm::vec3(0.0f, 0.5f, 0.0f),
                                         .range = 1.2f});
            points.push_back(under);
        }
    }
    result.groundPoints = spots;
    result.groundPoints.insert(result.groundPoints.end(), points.begin(), points.end());
    scene.lights = {{.name = "moon", .intensity = 0.05f, .direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f))}};
    // tan(30 degrees) = 0.577: the grid's rows (and, 16:9 or square, its columns) within the vertical field of view.
    const float height = std::max(half.x, half.y) / 0.577f;
    scene.camera = scene::lookAt({0.0f, height, 0.0f}, {0.0f, 0.0f, 0.0f}, glm::radians(60.0f), {0.0f, 0.0f, -1.0f});
    return result;
}

} // namespace penumbra::testing
