#include "penumbra/rhi/CubeMap.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>

namespace penumbra::rhi {
namespace {

// Rows of the rotation part: the world directions of view x, y and z (CubeMap.hpp's table).
struct FaceAxes {
    glm::vec3 x;
    glm::vec3 y;
    glm::vec3 z;
};

FaceAxes faceAxes(CubeFace face)
{
    switch (face) {
    case CubeFace::PositiveX:
        return {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}};
    case CubeFace::NegativeX:
        return {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    case CubeFace::PositiveY:
        return {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
    case CubeFace::NegativeY:
        return {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
    case CubeFace::PositiveZ:
        return {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    case CubeFace::NegativeZ:
        return {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    }
    return {};
}

CullMode swapped(CullMode mode)
{
    switch (mode) {
    case CullMode::Back:
        return CullMode::Front;
    case CullMode::Front:
        return CullMode::Back;
    case CullMode::None:
        return CullMode::None;
    }
    return mode;
}

} // namespace

glm::mat4 cubeFaceView(CubeFace face, const glm::vec3& position)
{
    const FaceAxes axes = faceAxes(face);
    glm::mat4 view(1.0f);
    for (int row = 0; row < 3; ++row) {
        const glm::vec3& axis = row == 0 ? axes.x : row == 1 ? axes.y : axes.z;
        for (int column = 0; column < 3; ++column)
            view[column][row] = axis[column];
        view[3][row] = -glm::dot(axis, position);
    }
    return view;
}

glm::mat4 cubeFaceProjection(const Conventions& conventions, float zNear, float zFar)
{
    return conventions.perspective(glm::half_pi<float>(), 1.0f, zNear, zFar);
}

float cubeFaceViewDepth(const glm::vec3& direction)
{
    return std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
}

bool flipsWinding(const glm::mat4& view) { return glm::determinant(glm::mat3(view)) < 0.0f; }

CullMode viewCullMode(const glm::mat4& view, CullMode worldCull)
{
    return flipsWinding(view) ? swapped(worldCull) : worldCull;
}

CullMode cubeFaceCullMode(CullMode worldCull) { return swapped(worldCull); }

} // namespace penumbra::rhi
