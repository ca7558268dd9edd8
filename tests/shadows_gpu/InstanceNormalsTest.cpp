// The vertex shaders derive each instance's normal matrix from its model matrix (shaders/instance.glsl): a sphere
// turned, stretched unevenly and mirrored by its transform is lit as the same sphere with its vertices and normals
// transformed on the host (normals by the inverse transpose, left unnormalized as the shaders leave them, so that
// they interpolate alike). The negative control transforms the host's normals by the model matrix itself, wrong under
// uneven scale, and the pictures then differ. The sun casts no shadow: the two spheres' bounds, and so the cascades'
// fits, are not the same.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <utility>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kWidth = 160;
constexpr std::uint32_t kHeight = 120;

// Turned about a slanted axis, stretched 2 : 0.5 : 1 and mirrored in y.
glm::mat4 sphereTransform()
{
    const glm::mat4 turned =
        glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, 1.2f, -0.2f}), 0.8f, glm::normalize(glm::vec3(1, 2, 3)));
    return glm::scale(turned, {2.0f, -0.5f, 1.0f});
}

// The sphere, its triangles turned round: the mirroring transform turns them back to face outwards.
scene::MeshData mirroredSphere()
{
    scene::MeshData sphere = scene::makeSphere(1.0f, 32, 16);
    for (std::size_t i = 0; i + 2 < sphere.indices.size(); i += 3)
        std::swap(sphere.indices[i + 1], sphere.indices[i + 2]);
    return sphere;
}

// The sphere with `transform` applied on the host: positions by it, normals by `normalMatrix`, unnormalized.
scene::MeshData transformedOnTheHost(const glm::mat4& transform, const glm::mat3& normalMatrix)
{
    scene::MeshData sphere = mirroredSphere();
    sphere.bounds = {};
    for (scene::Vertex& v : sphere.vertices) {
        v.position = glm::vec3(transform * glm::vec4(v.position, 1.0f));
        v.normal = normalMatrix * v.normal;
        sphere.bounds.extend(v.position);
    }
    return sphere;
}

scene::Scene sphereScene(scene::MeshData mesh, const glm::mat4& transform)
{
    scene::Scene scene;
    const std::uint32_t material = scene.addMaterial({.name = "sphere", .baseColor = {0.8f, 0.7f, 0.6f, 1.0f}});
    scene.addObject("sphere", scene.addMesh(std::move(mesh)), material, transform);
    scene.lights.push_back({.name = "sun",
                            .intensity = 3.0f,
                            .direction = glm::normalize(glm::vec3(-0.4f, -1, -0.6f)),
                            .shadowStrength = 0.0f});
    scene.camera = scene::lookAt({0.0f, 2.0f, 6.0f}, {0.3f, 1.2f, -0.2f}, glm::radians(45.0f));
    scene.validate();
    return scene;
}

using InstanceNormalsTest = GpuTest;

TEST_F(InstanceNormalsTest, ShaderNormalMatricesMatchTheHostsInverseTranspose)
{
    const glm::mat4 transform = sphereTransform();
    const render::FrameDesc frame = litFrame(kWidth, kHeight, true, 1);
    const rhi::Image onTheGpu = renderLit(*device, sphereScene(mirroredSphere(), transform), frame);
    const glm::mat3 inverseTranspose = glm::transpose(glm::inverse(glm::mat3(transform)));
    const rhi::Image onTheHost =
        renderLit(*device, sphereScene(transformedOnTheHost(transform, inverseTranspose), glm::mat4(1.0f)), frame);
    const rhi::Image byTheModel =
        renderLit(*device, sphereScene(transformedOnTheHost(transform, glm::mat3(transform)), glm::mat4(1.0f)), frame);
    savePicture(onTheGpu, "instance-normals-" + configuration());

    // The sphere covers some 15 % of the frame; rounding moves a few edge pixels and shading by a level.
    EXPECT_LT(differingShare(onTheGpu, onTheHost, 2), 0.002);
    EXPECT_GT(differingShare(onTheGpu, byTheModel, 2), 0.03); // the negative control
}

} // namespace
} // namespace penumbra::testing
