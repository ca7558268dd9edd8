#include "penumbra/scene/LocalLights.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace penumbra::scene {
namespace {

const std::set<std::string> kStanding{"standing cube",     "turned cube",       "standing sphere", "large sphere",
                                      "standing cylinder", "unshadowed pillar", "tall pillar",     "wall"};
const std::set<std::string> kFloating{"floating cube",  "tumbling cube", "dither sphere",
                                      "lying cylinder", "clip panel",    "long beam"};

const Object& object(const Scene& scene, const std::string& name)
{
    const auto index = scene.findObject(name);
    if (!index)
        throw std::runtime_error("no object " + name);
    return scene.objects[*index];
}

float lowestVertexY(const Scene& scene, const Object& o)
{
    float lowest = INFINITY;
    for (const Vertex& v : scene.meshOf(o).vertices)
        lowest = std::min(lowest, (o.transform * glm::vec4(v.position, 1.0f)).y);
    return lowest;
}

TEST(TestScenesTest, BothScenesValidate)
{
    EXPECT_NO_THROW(scenes::makeShadowTestScene().validate());
    EXPECT_NO_THROW(scenes::makeSingleLightScene().validate());
}

TEST(TestScenesTest, HasTheGroundAndEveryNamedObject)
{
    const Scene scene = scenes::makeShadowTestScene();
    EXPECT_EQ(scene.objects.size(), 1 + kStanding.size() + kFloating.size());
    const Object& ground = object(scene, "ground");
    EXPECT_EQ(ground.worldBounds.min, glm::vec3(-30, 0, -30));
    EXPECT_EQ(ground.worldBounds.max, glm::vec3(30, 0, 30));
}

TEST(TestScenesTest, StandingObjectsTouchTheGroundExactly)
{
    const Scene scene = scenes::makeShadowTestScene();
    for (const std::string& name : kStanding) {
        SCOPED_TRACE(name);
        EXPECT_EQ(lowestVertexY(scene, object(scene, name)), 0.0f);
    }
}

TEST(TestScenesTest, FloatingObjectsClearTheGround)
{
    const Scene scene = scenes::makeShadowTestScene();
    for (const std::string& name : kFloating) {
        SCOPED_TRACE(name);
        EXPECT_GT(object(scene, name).worldBounds.min.y, 1.0f);
    }
}

TEST(TestScenesTest, ObjectsDoNotIntersectEachOther)
{
    const Scene scene = scenes::makeShadowTestScene();
    for (std::size_t i = 1; i < scene.objects.size(); ++i) {
        for (std::size_t j = i + 1; j < scene.objects.size(); ++j) {
            const Bounds& a = scene.objects[i].worldBounds;
            const Bounds& b = scene.objects[j].worldBounds;
            const bool overlap = glm::all(glm::lessThan(a.min, b.max)) && glm::all(glm::lessThan(b.min, a.max));
            EXPECT_FALSE(overlap) << scene.objects[i].name << " and " << scene.objects[j].name;
        }
    }
}

TEST(TestScenesTest, LongBeamRunsFromTheViewToBehindTheCamera)
{
    const Scene scene = scenes::makeShadowTestScene();
    const Bounds& beam = object(scene, "long beam").worldBounds;
    EXPECT_GE(beam.size().z, 80.0f);
    float nearest = INFINITY;
    float farthest = -INFINITY;
    for (const glm::vec3& corner : beam.corners()) {
        const float depth = glm::dot(corner - scene.camera.position, scene.camera.forward);
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    EXPECT_LT(nearest, -20.0f) << "reaches far behind the camera's near plane";
    EXPECT_GT(farthest, 30.0f) << "and far into the view";
}

TEST(TestScenesTest, MaterialsCoverEveryShadowCase)
{
    const Scene scene = scenes::makeShadowTestScene();
    EXPECT_EQ(scene.materialOf(object(scene, "clip panel")).caster, CasterMode::Clip);
    EXPECT_EQ(scene.materialOf(object(scene, "dither sphere")).caster, CasterMode::Dither);
    EXPECT_FALSE(scene.materialOf(object(scene, "unshadowed pillar")).receiveShadows);
    int clip = 0, dither = 0, notReceiving = 0;
    for (const Object& o : scene.objects) {
        const Material& m = scene.materialOf(o);
        clip += m.caster == CasterMode::Clip;
        dither += m.caster == CasterMode::Dither;
        notReceiving += !m.receiveShadows;
    }
    EXPECT_EQ(clip, 1);
    EXPECT_EQ(dither, 1);
    EXPECT_EQ(notReceiving, 1);
}

TEST(TestScenesTest, FourLightsNinetyDegreesApartAtOnePitch)
{
    const Scene scene = scenes::makeShadowTestScene();
    ASSERT_EQ(scene.lights.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        const DirectionalLight& light = scene.lights[i];
        const DirectionalLight& next = scene.lights[(i + 1) % 4];
        EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-6f);
        EXPECT_NEAR(light.direction.y, -std::sin(glm::radians(50.0f)), 1e-6f);
        const glm::vec2 a = glm::normalize(glm::vec2(light.direction.x, light.direction.z));
        const glm::vec2 b = glm::normalize(glm::vec2(next.direction.x, next.direction.z));
        EXPECT_NEAR(glm::dot(a, b), 0.0f, 1e-6f);
        EXPECT_NE(light.color, next.color);
    }
    const Scene single = scenes::makeSingleLightScene();
    ASSERT_EQ(single.lights.size(), 1u);
    EXPECT_EQ(single.lights[0].direction, scene.lights[0].direction);
    EXPECT_EQ(single.objects.size(), scene.objects.size());
}

TEST(TestScenesTest, CameraLooksAtTheSceneFromAbove)
{
    const Camera& camera = scenes::makeShadowTestScene().camera;
    EXPECT_EQ(camera.position, glm::vec3(0, 8, -20));
    EXPECT_NEAR(glm::dot(camera.forward, glm::normalize(glm::vec3(0, -8, 25))), 1.0f, 1e-6f);
}

TEST(TestScenesTest, UnshadowedPillarStandsInTheFloatingCubesKeyShadow)
{
    const Scene scene = scenes::makeSingleLightScene();
    const truth::RayCaster caster(scene);
    const Object& pillar = object(scene, "unshadowed pillar");
    const glm::vec3 topCentre{pillar.worldBounds.center().x, pillar.worldBounds.max.y + 1e-3f,
                              pillar.worldBounds.center().z};
    const auto hit = caster.closestHit(topCentre, -scene.lights[0].direction);
    ASSERT_TRUE(hit);
    EXPECT_EQ(scene.objects[hit->object].name, "floating cube");
}

} // namespace
} // namespace penumbra::scene

namespace penumbra::scene {
namespace {

TEST(ForestSceneTest, HasTheTerrainFiveTreesAndOneSun)
{
    const Scene forest = scenes::makeForestScene();
    EXPECT_EQ(forest.meshOf(object(forest, "terrain")).triangleCount(), 2450u);
    for (int i = 1; i <= 5; ++i) {
        const std::string tree = "tree " + std::to_string(i);
        const std::uint32_t triangles = forest.meshOf(object(forest, tree + " wood")).triangleCount() +
                                        forest.meshOf(object(forest, tree + " leaves")).triangleCount();
        EXPECT_GT(triangles, 4500u) << tree;
        EXPECT_LT(triangles, 5500u) << tree;
        const Material& leaves = forest.materialOf(object(forest, tree + " leaves"));
        EXPECT_EQ(leaves.caster, CasterMode::Clip);
        EXPECT_TRUE(leaves.doubleSided) << "leaf cards are drawn and cast from both faces";
        ASSERT_TRUE(leaves.texture(TextureSlot::BaseColor));
    }
    ASSERT_EQ(forest.lights.size(), 1u);
    EXPECT_EQ(forest.objects.size(), 11u);
}

TEST(ForestSceneTest, LeafTextureCutsOutLeaves)
{
    const Scene forest = scenes::makeForestScene();
    const TextureImage& leaf = forest.textures.at(0);
    std::size_t opaque = 0, clear = 0;
    for (std::size_t i = 3; i < leaf.rgba.size(); i += 4) {
        opaque += leaf.rgba[i] == 255;
        clear += leaf.rgba[i] == 0;
    }
    const std::size_t texels = leaf.rgba.size() / 4;
    EXPECT_GT(opaque, texels / 5) << "the leaves cover a good part of the card";
    EXPECT_GT(clear, texels / 5) << "and leave holes between them";
}

TEST(ForestSceneTest, IsTheSameEveryTimeAndTheCameraStandsAboveTheGround)
{
    const Scene a = scenes::makeForestScene(), b = scenes::makeForestScene();
    const MeshData& leavesA = a.meshOf(object(a, "tree 3 leaves"));
    const MeshData& leavesB = b.meshOf(object(b, "tree 3 leaves"));
    ASSERT_EQ(leavesA.vertices.size(), leavesB.vertices.size());
    for (std::size_t i = 0; i < leavesA.vertices.size(); ++i)
        EXPECT_EQ(leavesA.vertices[i].position, leavesB.vertices[i].position);
    const truth::RayCaster rays(a, truth::RayKind::Camera);
    const std::optional<truth::Hit> below = rays.closestHit(a.camera.position, {0.0f, -1.0f, 0.0f});
    ASSERT_TRUE(below) << "terrain under the camera";
    EXPECT_NEAR(below->distance, 1.7f, 0.01f);
}

} // namespace
} // namespace penumbra::scene

namespace penumbra::scene {
namespace {

TEST(StreetSceneTest, HasTheLampsShopWindowsMoonAndCars)
{
    const Scene street = scenes::makeStreetScene();
    EXPECT_NO_THROW(street.validate());
    ASSERT_EQ(street.spotLights.size(), scenes::kStreetLamps);
    ASSERT_EQ(street.pointLights.size(), scenes::kStreetShopWindows);
    ASSERT_EQ(street.lights.size(), 1u);
    EXPECT_EQ(street.lights[0].name, "moon");
    EXPECT_LT(street.lights[0].intensity, 0.2f);
    for (const SpotLight& lamp : street.spotLights)
        EXPECT_EQ(lamp.direction, glm::vec3(0.0f, -1.0f, 0.0f)) << lamp.name;
    for (std::uint32_t i = 1; i <= scenes::kStreetCars; ++i) {
        EXPECT_TRUE(street.findObject("car " + std::to_string(i) + "/0")) << i;
        EXPECT_TRUE(street.findObject("car " + std::to_string(i) + "/1")) << i;
    }
    // A few hundred metres long, and cheap: a handful of meshes shared by every object.
    const Bounds bounds = street.worldBounds();
    EXPECT_GT(bounds.max.z - bounds.min.z, 300.0f);
    EXPECT_LE(street.meshes.size(), 4u);
}

// Ten cars spread over the street drive down their lane, as dynamic objects, and wrap round at the far end; the
// parked cars stay put and no moving car meets a parked one.
TEST(StreetSceneTest, MovingCarsDriveDownTheirLaneAndWrapRound)
{
    const Scene parked = scenes::makeStreetScene();
    Scene street = parked;
    const float seconds = 30.0f; // 300 m: every car has wrapped round or is about to
    scenes::driveStreetCars(street, seconds);
    EXPECT_NO_THROW(street.validate());
    std::uint32_t moving = 0;
    for (std::size_t o = 0; o < street.objects.size(); ++o) {
        const Object& now = street.objects[o];
        const Object& before = parked.objects[o];
        if (now.mobility == Mobility::Static) {
            EXPECT_EQ(now.transform, before.transform) << now.name;
            continue;
        }
        ASSERT_EQ(now.name.rfind("car ", 0), 0u) << now.name;
        moving += now.name.back() == '0';
        EXPECT_NEAR(std::abs(now.transform[3].x), scenes::kStreetLaneX, 1e-5f) << now.name;
        const float driven = std::fmod(before.transform[3].z - now.transform[3].z + 384.0f, 384.0f);
        EXPECT_NEAR(driven, scenes::streetCarDistance(seconds), 1e-3f) << now.name;
        EXPECT_GE(now.worldBounds.min.z, -192.0f - 2.2f) << now.name;
        EXPECT_LE(now.worldBounds.max.z, 192.0f + 2.2f) << now.name;
        for (const Object& other : street.objects) {
            if (other.name.rfind("car ", 0) != 0 || other.mobility != Mobility::Static)
                continue;
            EXPECT_FALSE(
                now.worldBounds.max.x > other.worldBounds.min.x && other.worldBounds.max.x > now.worldBounds.min.x &&
                now.worldBounds.max.z > other.worldBounds.min.z && other.worldBounds.max.z > now.worldBounds.min.z)
                << now.name << " meets " << other.name;
        }
    }
    EXPECT_EQ(moving, scenes::kStreetMovingCars);
    Scene notStreet = scenes::makeShadowTestScene();
    EXPECT_THROW(scenes::driveStreetCars(notStreet, 0.0f), SceneError);
}

TEST(StreetSceneTest, LocalLightsRunFromTheCameraOutwards)
{
    const Scene street = scenes::makeStreetScene();
    const auto distance = [&](glm::vec3 p) { return glm::length(p - street.camera.position); };
    for (std::size_t i = 4; i < street.spotLights.size(); i += 4)
        EXPECT_GT(distance(street.spotLights[i].position), distance(street.spotLights[i - 4].position)) << i;
    for (std::size_t i = 2; i < street.pointLights.size(); i += 2)
        EXPECT_GT(distance(street.pointLights[i].position), distance(street.pointLights[i - 2].position)) << i;
}

TEST(LocalLightsTest, KeepFirstLocalLightsTakesSpotLightsThenPointLights)
{
    const Scene street = scenes::makeStreetScene();
    EXPECT_EQ(localLightCount(street), scenes::kStreetLamps + scenes::kStreetShopWindows);
    for (const std::uint32_t n : {0u, 16u, 256u, 300u, 320u, 1000u}) {
        Scene kept = street;
        keepFirstLocalLights(kept, n);
        EXPECT_EQ(localLightCount(kept), std::min(n, scenes::kStreetLamps + scenes::kStreetShopWindows)) << n;
        ASSERT_EQ(kept.spotLights.size(), std::min(n, scenes::kStreetLamps)) << n;
        for (std::size_t i = 0; i < kept.spotLights.size(); ++i)
            EXPECT_EQ(kept.spotLights[i].name, street.spotLights[i].name);
        for (std::size_t i = 0; i < kept.pointLights.size(); ++i)
            EXPECT_EQ(kept.pointLights[i].name, street.pointLights[i].name);
        EXPECT_EQ(kept.lights.size(), 1u);
    }
}

} // namespace
} // namespace penumbra::scene
