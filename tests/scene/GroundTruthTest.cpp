#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <map>

namespace penumbra::truth {
namespace {

TEST(GroundTruthTest, CentrePixelHitsWhatTheCameraLooksAt)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    const RayCaster cameraRays(scene, RayKind::Camera);
    // Odd size: the centre pixel's sample is exactly on the view axis.
    const CpuGBuffer gbuffer = traceGBuffer(scene, cameraRays, scene.camera, 101, 101);
    const GBufferSample& centre = gbuffer.at(50, 50);
    ASSERT_TRUE(centre.hit());
    EXPECT_EQ(scene.objects[centre.object].name, "ground");
    EXPECT_NEAR(glm::length(centre.position - glm::vec3(0, 0, 5)), 0.0f, 1e-3f); // the lookAt target
    EXPECT_NEAR(glm::dot(centre.normal, glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
    EXPECT_NEAR(centre.viewDepth, glm::length(glm::vec3(0, -8, 25)), 1e-3f);
}

TEST(GroundTruthTest, RowZeroIsTheTopOfThePicture)
{
    scene::Scene scene;
    scene.addObject("box", scene.addMesh(scene::makeBox({3, 1, 1})), scene.addMaterial({}),
                    glm::translate(glm::mat4(1.0f), glm::vec3(0, 2, 0)));
    scene.camera = scene::lookAt({0, 0, 10}, {0, 0, 0}, glm::radians(60.0f));
    const CpuGBuffer gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, 64, 48);
    EXPECT_TRUE(gbuffer.at(32, 12).hit()); // upper half: the box above the axis
    EXPECT_FALSE(gbuffer.at(32, 36).hit()); // lower half: nothing
    EXPECT_FALSE(gbuffer.at(0, 12).hit()); // left of the 6-unit box at this distance
}

// One mesh of a box (its faces keep their own vertices) and a card apart from it: the box's faces are one surface,
// the card another, as the leaf cards of one tree are.
TEST(GroundTruthTest, SamplesTellTheConnectedPiecesOfAMeshApart)
{
    scene::MeshData mesh = scene::makeBox({1, 1, 1});
    const scene::MeshData card = scene::makePlane(1.0f);
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (scene::Vertex v : card.vertices) {
        v.position = glm::vec3(v.position.z, v.position.x, 0.0f) + glm::vec3(3.0f, 0.0f, 0.0f);
        v.normal = {0.0f, 0.0f, 1.0f};
        mesh.vertices.push_back(v);
    }
    for (const std::uint32_t index : card.indices)
        mesh.indices.push_back(first + index);
    updateBounds(mesh);
    scene::Scene scene;
    scene.addObject("box and card", scene.addMesh(std::move(mesh)), scene.addMaterial({}), glm::mat4(1.0f));
    scene.camera = scene::lookAt({4.0f, 4.0f, 10.0f}, {1.5f, 0.0f, 0.0f}, glm::radians(50.0f));
    const CpuGBuffer gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, 96, 64);
    std::map<std::uint32_t, std::map<int, std::size_t>> facesBySurface; // surface -> face normal axis -> samples
    for (const GBufferSample& sample : gbuffer.samples)
        if (sample.hit()) {
            const glm::vec3 n = glm::abs(sample.normal);
            const int axis = n.x > 0.9f ? 0 : n.y > 0.9f ? 1 : 2;
            ++facesBySurface[sample.surface][sample.position.x > 2.0f ? 3 : axis];
        }
    ASSERT_EQ(facesBySurface.size(), 2u);
    const std::map<int, std::size_t>& box = facesBySurface.begin()->second;
    const std::map<int, std::size_t>& other = std::next(facesBySurface.begin())->second;
    EXPECT_EQ(box.size(), 3u) << "three faces of the box in view, one surface";
    EXPECT_EQ(other.size(), 1u);
    EXPECT_EQ(other.begin()->first, 3) << "the card alone";
}

TEST(GroundTruthTest, SamplesProjectBackToTheirPixelCentres)
{
    const scene::Scene scene = scenes::makeSingleLightScene();
    constexpr std::uint32_t width = 80, height = 60;
    const CpuGBuffer gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, width, height);
    const scene::Camera& camera = scene.camera;
    const glm::mat4 viewProjection =
        glm::perspectiveRH_ZO(camera.fovY, float(width) / float(height), camera.nearPlane, camera.farPlane) *
        camera.view();
    int checked = 0;
    for (std::uint32_t y = 0; y < height; y += 7) {
        for (std::uint32_t x = 0; x < width; x += 5) {
            const GBufferSample& sample = gbuffer.at(x, y);
            if (!sample.hit())
                continue;
            const glm::vec4 clip = viewProjection * glm::vec4(sample.position, 1.0f);
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            // NDC y up, row 0 at the top.
            EXPECT_NEAR((ndc.x + 1.0f) * 0.5f * width, x + 0.5f, 2e-3f);
            EXPECT_NEAR((1.0f - ndc.y) * 0.5f * height, y + 0.5f, 2e-3f);
            EXPECT_NEAR(clip.w, sample.viewDepth, 1e-3f * sample.viewDepth);
            ++checked;
        }
    }
    EXPECT_GT(checked, 50);
}

TEST(GroundTruthTest, ShadowUnderAFloatingBoxForAVerticalLight)
{
    scene::Scene scene;
    const std::uint32_t plain = scene.addMaterial({});
    scene.addObject("ground", scene.addMesh(scene::makePlane(20.0f)), plain, glm::mat4(1.0f));
    scene.addObject("box", scene.addMesh(scene::makeBox({1, 1, 1})), plain,
                    glm::translate(glm::mat4(1.0f), glm::vec3(0, 3, 0)));
    // Seen from a slant, so the ground under the box is partly visible beside it.
    scene.camera = scene::lookAt({0, 12, -12}, {0, 0, 0}, glm::radians(40.0f));
    const scene::DirectionalLight light{.direction = {0, -1, 0}};
    const CpuGBuffer gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, 65, 65);
    const LightVisibilityMask mask = traceLightVisibility(scene, RayCaster(scene), gbuffer, light);
    std::map<LightVisibility, int> counts;
    for (std::uint32_t y = 0; y < mask.height; ++y) {
        for (std::uint32_t x = 0; x < mask.width; ++x) {
            const GBufferSample& sample = gbuffer.at(x, y);
            ++counts[mask.at(x, y)];
            if (!sample.hit() || scene.objects[sample.object].name != "ground")
                continue;
            const bool underBox = std::abs(sample.position.x) < 1.0f && std::abs(sample.position.z) < 1.0f;
            const bool clearOfBox = std::abs(sample.position.x) > 1.0f || std::abs(sample.position.z) > 1.0f;
            if (underBox) {
                EXPECT_EQ(mask.at(x, y), LightVisibility::Shadowed) << x << ", " << y;
            } else if (clearOfBox) {
                EXPECT_EQ(mask.at(x, y), LightVisibility::Lit) << x << ", " << y;
            }
        }
    }
    EXPECT_GT(counts[LightVisibility::Shadowed], 0);
    EXPECT_GT(counts[LightVisibility::Lit], 0);
    EXPECT_GT(counts[LightVisibility::FacingAway], 0); // the box's sides, lit from straight above
}

TEST(GroundTruthTest, TestSceneMaskHasEveryCategory)
{
    const scene::Scene scene = scenes::makeSingleLightScene();
    const CpuGBuffer gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, 160, 90);
    const LightVisibilityMask mask = traceLightVisibility(scene, RayCaster(scene), gbuffer, scene.lights[0]);
    std::map<LightVisibility, int> counts;
    for (const LightVisibility v : mask.pixels)
        ++counts[v];
    for (const LightVisibility v : {LightVisibility::Background, LightVisibility::Lit, LightVisibility::Shadowed,
                                    LightVisibility::FacingAway, LightVisibility::NotReceiving})
        EXPECT_GT(counts[v], 0) << static_cast<int>(v);
    const std::uint32_t pillar = *scene.findObject("unshadowed pillar");
    for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
        if (gbuffer.samples[i].object == pillar) {
            EXPECT_EQ(mask.pixels[i], LightVisibility::NotReceiving);
        }
    }
}

TEST(GroundTruthTest, WrongRayKindIsRejected)
{
    const scene::Scene scene = scenes::makeSingleLightScene();
    const RayCaster shadowRays(scene);
    EXPECT_THROW(traceGBuffer(scene, shadowRays, scene.camera, 4, 4), std::invalid_argument);
    const RayCaster cameraRays(scene, RayKind::Camera);
    const CpuGBuffer gbuffer = traceGBuffer(scene, cameraRays, scene.camera, 4, 4);
    EXPECT_THROW(traceLightVisibility(scene, cameraRays, gbuffer, scene.lights[0]), std::invalid_argument);
}

} // namespace
} // namespace penumbra::truth
