#include "GltfLoaderFixture.hpp"

#include <fmt/format.h>

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/scene/SceneDefaults.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <unistd.h>

namespace penumbra::scene {
namespace {

TEST_F(GltfLoaderTest, HierarchyMultipliesTransformsInOrder)
{
    GltfBuilder b;
    const int mesh = testing::addCubeMesh(b, "Cube", -1);
    const int child = b.add("nodes", {{"name", "child"},
                                      {"mesh", mesh},
                                      {"translation", {1, 0, 0}},
                                      {"rotation", {0, 0.7071068, 0, 0.7071068}},
                                      {"scale", {2, 1, 1}}});
    // Column-major: a translation by (0, 10, 0).
    b.addRoot(b.add("nodes", {{"name", "parent"},
                              {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 10, 0, 1}},
                              {"children", {child}}}));
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    ASSERT_EQ(loaded.scene.objects.size(), 1u);
    const Object& object = loaded.scene.objects[0];
    EXPECT_EQ(object.name, "child");
    const glm::mat4 expected = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 10, 0)),
                                                      glm::radians(90.0f), glm::vec3(0, 1, 0)),
                                          glm::vec3(2, 1, 1));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(object.transform[c][r], expected[c][r], 1e-5f) << c << "," << r;
    // Scaled 2 along local x, turned onto world -z: the box spans z in [-2, 2], x in [0, 2].
    EXPECT_NEAR(object.worldBounds.min.z, -2.0f, 1e-5f);
    EXPECT_NEAR(object.worldBounds.max.x, 2.0f, 1e-5f);
    EXPECT_NEAR(object.worldBounds.min.y, 9.0f, 1e-5f);
}

// A node matrix's last row must be (0, 0, 0, 1) (glTF 2.0 section 3.5.3, decomposable to translation, rotation and
// scale): a projective one is refused naming the field, a writer's rounding within 1e-6 is read as (0, 0, 0, 1).
TEST_F(GltfLoaderTest, NodeMatricesOtherThanAffineAreRefused)
{
    const auto withMatrix = [](nlohmann::json matrix) {
        GltfBuilder b;
        b.addRoot(
            b.add("nodes", {{"name", "cube"}, {"mesh", testing::addCubeMesh(b, "Cube", -1)}, {"matrix", matrix}}));
        return b;
    };
    EXPECT_CONTAINS(errorOf(write(withMatrix({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 0, 1}))),
                    "/nodes/0/matrix: expected a last row (elements 3, 7, 11, 15) of 0, 0, 0, 1, as a matrix of "
                    "translation, rotation and scale has, got 0, 0, -1, 1");
    const gltf::GltfScene loaded =
        gltf::loadGltf(write(withMatrix({2, 0, 0, 1e-8, 0, 1, 0, 0, 0, 0, 1, 0, 0, 10, 0, 1.0000001})));
    ASSERT_EQ(loaded.scene.objects.size(), 1u);
    const glm::mat4& transform = loaded.scene.objects[0].transform;
    EXPECT_EQ(glm::vec4(transform[0][3], transform[1][3], transform[2][3], transform[3][3]), glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(transform[0][0], 2.0f);
    EXPECT_EQ(transform[3][1], 10.0f);
}

TEST_F(GltfLoaderTest, EveryIndexSizeAndNoIndicesGiveTheSameTriangles)
{
    const gltf::GltfScene reference = gltf::loadGltf(write(cubeScene(Component::UnsignedInt), "u32.gltf"));
    for (const Component component : {Component::UnsignedByte, Component::UnsignedShort}) {
        const gltf::GltfScene loaded = gltf::loadGltf(write(cubeScene(component), "small.gltf"));
        EXPECT_EQ(loaded.scene.meshes[0].indices, reference.scene.meshes[0].indices);
    }
    // Without indices: the indexed triangles' vertices written out three by three.
    GltfBuilder b = cubeScene();
    const MeshData& indexed = reference.scene.meshes[0];
    std::vector<glm::vec3> positions, normals;
    for (const std::uint32_t i : indexed.indices) {
        positions.push_back(indexed.vertices[i].position);
        normals.push_back(indexed.vertices[i].normal);
    }
    primitive(b) = {{"attributes", {{"POSITION", b.addPositions(positions)}, {"NORMAL", b.addNormals(normals)}}}};
    const gltf::GltfScene loaded = gltf::loadGltf(write(b, "none.gltf"));
    const MeshData& unindexed = loaded.scene.meshes[0];
    ASSERT_EQ(unindexed.indices.size(), 36u);
    for (std::size_t i = 0; i < 36; ++i)
        EXPECT_EQ(unindexed.vertices[unindexed.indices[i]].position, positions[i]);
}

TEST_F(GltfLoaderTest, InterleavedAttributesAndNormalizedTexCoords)
{
    GltfBuilder b;
    struct PositionNormal {
        glm::vec3 position, normal;
    };
    const std::vector<PositionNormal> vertices = {{{0, 0, 0}, {0, 0, 1}},
                                                  {{1, 0, 0}, {0, 0, 1}},
                                                  {{0, 1, 0}, {0, 0, 1}}};
    // Both attributes in one buffer view, 24 bytes a vertex, the normal 12 bytes in.
    const int position =
        b.addAccessor({reinterpret_cast<const std::uint8_t*>(vertices.data()), sizeof(PositionNormal) * 3}, 3, "VEC3",
                      Component::Float);
    const auto view = b.json()["accessors"][std::size_t(position)]["bufferView"].get<std::size_t>();
    b.json()["bufferViews"][view]["byteStride"] = sizeof(PositionNormal);
    const int normal = b.add("accessors", {{"bufferView", view},
                                           {"byteOffset", 12},
                                           {"count", 3},
                                           {"type", "VEC3"},
                                           {"componentType", int(Component::Float)}});
    const std::vector<std::uint16_t> uvs = {0, 0, 65535, 0, 0, 32768};
    const int uv = b.addAccessor({reinterpret_cast<const std::uint8_t*>(uvs.data()), uvs.size() * 2}, 3, "VEC2",
                                 Component::UnsignedShort, true);
    const int mesh =
        b.add("meshes",
              {{"primitives", {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}}}}}});
    b.addRoot(b.add("nodes", {{"mesh", mesh}}));
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    const MeshData& read = loaded.scene.meshes.at(0);
    ASSERT_EQ(read.vertices.size(), 3u);
    EXPECT_EQ(read.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(read.vertices[i].position, vertices[i].position);
        EXPECT_EQ(read.vertices[i].normal, vertices[i].normal);
    }
    EXPECT_EQ(read.vertices[1].uv, glm::vec2(1.0f, 0.0f));
    EXPECT_FLOAT_EQ(read.vertices[2].uv.y, 32768.0f / 65535.0f);
}

TEST_F(GltfLoaderTest, MissingNormalsAreComputedFlat)
{
    GltfBuilder b = cubeScene();
    primitive(b)["attributes"].erase("NORMAL");
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    const MeshData& mesh = loaded.scene.meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 36u);
    for (std::size_t t = 0; t < 12; ++t) {
        const Vertex* v = &mesh.vertices[mesh.indices[3 * t]];
        const glm::vec3 face = glm::normalize(glm::cross(v[1].position - v[0].position, v[2].position - v[0].position));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::dot(v[k].normal, face), 1.0f, 1e-6f);
        // Outward: the cube is centred on the origin.
        EXPECT_GT(glm::dot(face, v[0].position), 0.0f);
    }
}

TEST_F(GltfLoaderTest, MirroringNodesGetReversedWindingSoOutsidesStayFrontFacing)
{
    GltfBuilder b = cubeScene();
    b.json()["nodes"][0]["scale"] = {-1, 1, 1};
    b.addRoot(b.add("nodes", {{"name", "plain"}, {"mesh", 0}, {"translation", {5, 0, 0}}}));
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    ASSERT_EQ(loaded.scene.objects.size(), 2u);
    EXPECT_NE(loaded.scene.objects[0].mesh, loaded.scene.objects[1].mesh) << "the mirrored node needs its own copy";
    for (const Object& object : loaded.scene.objects) {
        const MeshData& mesh = loaded.scene.meshOf(object);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(object.transform)));
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            glm::vec3 world[3];
            for (int k = 0; k < 3; ++k)
                world[k] =
                    glm::vec3(object.transform * glm::vec4(mesh.vertices[mesh.indices[3 * t + k]].position, 1.0f));
            const glm::vec3 face = glm::cross(world[1] - world[0], world[2] - world[0]);
            const glm::vec3 normal = normalMatrix * mesh.vertices[mesh.indices[3 * t]].normal;
            EXPECT_GT(glm::dot(face, normal), 0.0f) << object.name << " triangle " << t;
        }
    }
}

TEST_F(GltfLoaderTest, CamerasByOrderAndByName)
{
    GltfBuilder b = cubeScene();
    b.add("cameras",
          {{"name", "first"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.5}, {"zfar", 50}}}});
    b.add("cameras", {{"name", "second"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.2}}}});
    b.addRoot(b.add("nodes", {{"camera", 0}, {"translation", {0, 0, 10}}}));
    // Turned 90 degrees about y: looks down world -x.
    b.addRoot(b.add(
        "nodes",
        {{"name", "side"}, {"camera", 1}, {"translation", {10, 0, 0}}, {"rotation", {0, 0.7071068, 0, 0.7071068}}}));
    const std::filesystem::path path = write(b);

    const Camera first = gltf::loadGltf(path).scene.camera;
    EXPECT_FLOAT_EQ(first.fovY, 0.5f);
    EXPECT_EQ(first.position, glm::vec3(0, 0, 10));
    EXPECT_NEAR(glm::dot(first.forward, glm::vec3(0, 0, -1)), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(first.farPlane, 50.0f);

    for (const char* name : {"second", "side"}) {
        const Camera second = gltf::loadGltf(path, {.camera = name}).scene.camera;
        EXPECT_FLOAT_EQ(second.fovY, 0.9f);
        EXPECT_NEAR(glm::dot(second.forward, glm::vec3(-1, 0, 0)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(second.up, glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
        // No zfar: the far plane lies behind the whole scene (the cube's far corner is 11.1 away).
        EXPECT_GT(second.farPlane, 11.1f);
    }
    const std::string message = errorOf(path, {.camera = "missing"});
    EXPECT_CONTAINS(message, "scene.gltf: no camera named 'missing'");
    EXPECT_CONTAINS(message, "'first', 'second'");
}

TEST_F(GltfLoaderTest, PunctualLightsOfAllThreeKinds)
{
    const gltf::GltfScene loaded = gltf::loadGltf(write(testing::exampleScene()));
    const Scene& scene = loaded.scene;
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_EQ(scene.spotLights.size(), 1u);
    ASSERT_EQ(scene.pointLights.size(), 1u);
    EXPECT_EQ(scene.lights[0].name, "sun");
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 2.5f);
    EXPECT_NEAR(scene.lights[0].direction.y, -std::sin(glm::radians(50.0f)), 1e-5f); // 50 degrees down
    const SpotLight& spot = scene.spotLights[0];
    EXPECT_NEAR(glm::dot(spot.direction, glm::vec3(0, -1, 0)), 1.0f, 1e-6f); // node -z turned to point down
    EXPECT_EQ(spot.position, glm::vec3(0, 6, 0));
    EXPECT_FLOAT_EQ(spot.innerAngle, 0.3f); // half-angles, as glTF's
    EXPECT_FLOAT_EQ(spot.outerAngle, 0.5f);
    EXPECT_FLOAT_EQ(spot.range, 12.0f);
    EXPECT_EQ(spot.color, glm::vec3(1.0f, 0.9f, 0.7f));
    const PointLight& point = scene.pointLights[0];
    EXPECT_EQ(point.position, glm::vec3(-3, 3, 3));
    EXPECT_FLOAT_EQ(point.range, gltf::kDefaultRangePerSqrtIntensity * std::sqrt(5.0f)); // no range in the file
    EXPECT_EQ(scene.camera.position, glm::vec3(0, 5, 9));
}

TEST_F(GltfLoaderTest, AlphaModesBecomeCasterModes)
{
    const Scene scene = gltf::loadGltf(write(testing::exampleScene())).scene;
    const auto material = [&](const char* object) {
        return scene.materialOf(scene.objects.at(*scene.findObject(object)));
    };
    EXPECT_EQ(material("standing cube").caster, CasterMode::On);
    EXPECT_EQ(material("floating cube").caster, CasterMode::Clip);
    EXPECT_FLOAT_EQ(material("floating cube").alphaCutoff, 0.4f);
    EXPECT_EQ(material("blend cube").caster, CasterMode::Dither);
    EXPECT_FLOAT_EQ(material("blend cube").baseColor.a, 0.5f);
    EXPECT_FLOAT_EQ(material("standing cube").baseColor.r, 0.8f);
    EXPECT_FLOAT_EQ(material("standing cube").metallic, 0.0f);
}

TEST_F(GltfLoaderTest, BaseColorTextureIsDecodedToRgba8)
{
    GltfBuilder b = cubeScene();
    const std::vector<std::uint8_t> texels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 0};
    const int image = b.addPngImage(2, 2, texels);
    const int texture = b.add("textures", {{"source", image}});
    primitive(b)["material"] =
        b.add("materials",
              {{"name", "textured"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
    for (const char* name : {"textured.gltf", "textured.glb"}) {
        const Scene scene = gltf::loadGltf(write(b, name)).scene;
        ASSERT_EQ(scene.textures.size(), 1u);
        EXPECT_EQ(scene.textures[0].width, 2u);
        EXPECT_EQ(scene.textures[0].height, 2u);
        EXPECT_EQ(scene.textures[0].rgba, texels);
        const auto& baseColor = scene.materials.at(scene.objects[0].material).texture(TextureSlot::BaseColor);
        ASSERT_TRUE(baseColor.has_value());
        EXPECT_EQ(baseColor->image, 0u);
        EXPECT_EQ(baseColor->texCoord, 0u);
    }
}

// glTF samplers (section 5.26) map onto TextureSampler field by field; base colour textures are sRGB.
TEST_F(GltfLoaderTest, SamplersReachTheSceneTextures)
{
    const Scene scene =
        gltf::loadGltf(write(testing::sampledTexturesScene(
                           {{{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33648}, {"wrapT", 33071}},
                            nullptr,
                            {{"minFilter", 9729}, {"wrapT", 33648}},
                            {{"magFilter", 9729}, {"minFilter", 9985}, {"wrapS", 33071}}})))
            .scene;
    ASSERT_EQ(scene.textures.size(), 4u) << "one scene texture per glTF texture";
    const auto sampler = [&](int cube) {
        const Material& m = scene.materialOf(scene.objects.at(*scene.findObject("cube " + std::to_string(cube))));
        EXPECT_EQ(scene.textures.at(m.texture(TextureSlot::BaseColor)->image).colorSpace, TextureColorSpace::Srgb);
        return scene.textures.at(m.texture(TextureSlot::BaseColor)->image).sampler;
    };
    const TextureSampler nearestMirrored = sampler(0);
    EXPECT_EQ(nearestMirrored.magFilter, TextureFilter::Nearest);
    EXPECT_EQ(nearestMirrored.minFilter, TextureFilter::Nearest);
    EXPECT_EQ(nearestMirrored.mipFilter, TextureMipFilter::Linear);
    EXPECT_EQ(nearestMirrored.wrapS, TextureWrap::MirroredRepeat);
    EXPECT_EQ(nearestMirrored.wrapT, TextureWrap::ClampToEdge);
    const TextureSampler none = sampler(1); // glTF: repeat and auto filtering, which is trilinear here
    EXPECT_EQ(none.magFilter, TextureFilter::Linear);
    EXPECT_EQ(none.minFilter, TextureFilter::Linear);
    EXPECT_EQ(none.mipFilter, TextureMipFilter::Linear);
    EXPECT_EQ(none.wrapS, TextureWrap::Repeat);
    EXPECT_EQ(none.wrapT, TextureWrap::Repeat);
    const TextureSampler linearNoMips = sampler(2);
    EXPECT_EQ(linearNoMips.magFilter, TextureFilter::Linear) << "an undefined magFilter is auto: linear";
    EXPECT_EQ(linearNoMips.mipFilter, TextureMipFilter::None);
    EXPECT_EQ(linearNoMips.wrapS, TextureWrap::Repeat) << "wrapS defaults to REPEAT";
    EXPECT_EQ(linearNoMips.wrapT, TextureWrap::MirroredRepeat);
    const TextureSampler mipNearest = sampler(3);
    EXPECT_EQ(mipNearest.minFilter, TextureFilter::Linear);
    EXPECT_EQ(mipNearest.mipFilter, TextureMipFilter::Nearest);
    EXPECT_EQ(mipNearest.wrapS, TextureWrap::ClampToEdge);
}

TEST_F(GltfLoaderTest, UnknownSamplerCodesAreRefused)
{
    EXPECT_CONTAINS(errorOf(write(testing::sampledTexturesScene({{{"wrapS", 12345}}}))),
                    "scene.gltf: /samplers/0/wrapS: expected one of 33071, 33648, 10497, got 12345");
    EXPECT_CONTAINS(errorOf(write(testing::sampledTexturesScene({{{"minFilter", 9730}}}))),
                    "/samplers/0/minFilter: expected one of 9728, 9729, 9984, 9985, 9986, 9987, got 9730");
    EXPECT_CONTAINS(errorOf(write(testing::sampledTexturesScene({{{"magFilter", 9984}}}))),
                    "/samplers/0/magFilter: expected one of 9728, 9729, got 9984");
}

TEST_F(GltfLoaderTest, DefaultsForASceneWithoutLightsOrCamera)
{
    const gltf::GltfScene loaded = gltf::loadGltf(write(cubeScene()));
    EXPECT_TRUE(loaded.defaultLights);
    ASSERT_EQ(loaded.scene.lights.size(), 1u);
    const DirectionalLight& sun = loaded.scene.lights[0];
    const Camera& camera = loaded.scene.camera;
    EXPECT_EQ(sun.name, "default sun");
    // From above, from behind the camera (it lights what the camera sees) and from its left.
    EXPECT_NEAR(sun.direction.y, -std::sin(glm::radians(kDefaultSunElevationDegrees)), 1e-5f);
    EXPECT_GT(glm::dot(sun.direction, camera.forward), 0.3f);
    EXPECT_GT(glm::dot(sun.direction, camera.right()), 0.2f);
    // The framing camera sees every corner of the cube in front of it, between its planes; the cube's bounding
    // sphere fills most of the frame: its outline reaches 1 / 1.1 of the half field of view.
    const Bounds bounds = loaded.scene.worldBounds();
    for (const glm::vec3& corner : bounds.corners()) {
        const glm::vec3 view = glm::vec3(camera.view() * glm::vec4(corner, 1.0f));
        EXPECT_GT(-view.z, camera.nearPlane);
        EXPECT_LT(-view.z, camera.farPlane);
        EXPECT_LT(std::abs(view.y / view.z), std::tan(0.5f * camera.fovY));
    }
    const float distance = glm::length(bounds.center() - camera.position);
    const float outline = std::asin(0.5f * glm::length(bounds.size()) / distance);
    EXPECT_NEAR(std::tan(outline) / std::tan(0.5f * camera.fovY), 1.0f / 1.1f, 1e-3f);
    EXPECT_EQ(loaded.notes.size(), 2u);
}

TEST_F(GltfLoaderTest, FramingFitsTheNarrowerFieldOfViewOfATallFrame)
{
    const gltf::GltfScene wide = gltf::loadGltf(write(cubeScene()), {.aspect = 2.0f});
    const gltf::GltfScene tall = gltf::loadGltf(write(cubeScene()), {.aspect = 0.5f});
    const Bounds bounds = wide.scene.worldBounds();
    const float wideDistance = glm::length(bounds.center() - wide.scene.camera.position);
    const float tallDistance = glm::length(bounds.center() - tall.scene.camera.position);
    // The horizontal half field of view of the tall frame has half the vertical one's tangent.
    const float radius = 0.5f * glm::length(bounds.size());
    EXPECT_NEAR(std::tan(std::asin(radius / tallDistance)) / std::tan(std::asin(radius / wideDistance)), 0.5f, 1e-3f);
}

TEST_F(GltfLoaderTest, GlbAndExternalBufferLoadLikeDataUris)
{
    const GltfBuilder b = testing::exampleScene();
    const Scene inline_ = gltf::loadGltf(write(b)).scene;
    b.writeGltf(folder_ / "external.gltf", true);
    for (const std::filesystem::path& path : {write(b, "scene.glb"), folder_ / "external.gltf"}) {
        const Scene other = gltf::loadGltf(path).scene;
        ASSERT_EQ(other.meshes.size(), inline_.meshes.size()) << path;
        for (std::size_t m = 0; m < other.meshes.size(); ++m)
            EXPECT_EQ(other.meshes[m].indices, inline_.meshes[m].indices);
        EXPECT_EQ(other.objects.size(), inline_.objects.size());
    }
}

TEST_F(GltfLoaderTest, APrimitiveWithoutPositionIsSkippedWithANote)
{
    GltfBuilder b = cubeScene();
    nlohmann::json positionless = primitive(b);
    positionless["attributes"].erase("POSITION");
    b.json()["meshes"][0]["primitives"].push_back(positionless);
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    EXPECT_EQ(loaded.scene.objects.size(), 1u);
    std::string notes;
    for (const std::string& note : loaded.notes)
        notes += note + "\n";
    EXPECT_CONTAINS(notes, "mesh 0 ('Cube') primitive 1: no POSITION attribute: skipped");
}

TEST_F(GltfLoaderTest, ToleratedDeviationsAreNotedOncePerKind)
{
    GltfBuilder b = cubeScene();
    b.json()["accessors"][std::size_t(attribute(b, "POSITION"))]["max"] = {2.0, 2.0, 2.0};
    b.json()["accessors"][std::size_t(attribute(b, "POSITION"))]["min"] = {-2.0, -2.0, -2.0};
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    std::size_t mismatches = 0;
    for (const std::string& note : loaded.notes)
        mismatches +=
            note.find("tolerated: accessor min/max do not match its elements at /accessors/0") != std::string::npos;
    EXPECT_EQ(mismatches, 1u);
}

TEST_F(GltfLoaderTest, WrongTypesAreNamedByTheirJsonPointer)
{
    GltfBuilder b = cubeScene();
    b.json()["nodes"][0]["scale"] = -1;
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /nodes/0/scale: expected an array of 3 numbers, got -1");
    b.json()["nodes"][0].erase("scale");
    b.json()["accessors"][0]["bufferView"] = 99;
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /accessors/0/bufferView: expected an index of bufferViews");
}

// Out-of-memory requests are refused with a named limit before anything is allocated for them.

TEST_F(GltfLoaderTest, AHugeAccessorIsRefusedBeforeAllocation)
{
    GltfBuilder b = cubeScene();
    for (nlohmann::json& accessor : b.json()["accessors"]) {
        accessor.erase("bufferView");
        accessor["count"] = std::int64_t(1) << 31;
    }
    EXPECT_CONTAINS(errorOf(write(b)), "/count: 2147483648 elements, over the limit of 16777216");
}

TEST_F(GltfLoaderTest, AHugeTextureIsRefusedBeforeDecoding)
{
    const std::array<std::uint8_t, 4> texel{255, 255, 255, 255};
    GltfBuilder b = testing::sampledTexturesScene({nullptr});
    const int image = b.addPngImage(1, 1, texel);
    // The PNG header's IHDR width and height (RFC 2083, section 4.1.1) at bytes 16 to 23, set to 65535 each.
    const nlohmann::json& view =
        b.json()["bufferViews"][b.json()["images"][std::size_t(image)]["bufferView"].get<std::size_t>()];
    const std::size_t ihdr = view["byteOffset"].get<std::size_t>() + 16;
    for (std::size_t i = 0; i < 8; ++i)
        b.bin()[ihdr + i] = i % 4 < 2 ? 0x00 : 0xff;
    b.json()["textures"][0]["source"] = image;
    EXPECT_CONTAINS(errorOf(write(b)),
                    fmt::format("/images/{}: the picture is 65535x65535 texels, over the limits", image));
}

TEST_F(GltfLoaderTest, TooManyNodesAreRefused)
{
    GltfBuilder b = cubeScene();
    b.json()["nodes"] = nlohmann::json::array();
    for (int i = 0; i < 100001; ++i)
        b.json()["nodes"].push_back(nlohmann::json::object());
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /nodes: 100001 elements, over the limit of 100000");
}

// As many nodes as the limit allows load, one object each: the structure of a file that took the loader seconds
// while the JSON parser's depth check was quadratic in the length of an array (GltfFile.cpp, checkJsonDepth). How
// long it takes is `penumbra bench`'s business, not a unit test's.
TEST_F(GltfLoaderTest, AsManyNodesAsTheLimitLoad)
{
    GltfBuilder b = cubeScene();
    nlohmann::json& nodes = b.json()["nodes"];
    nlohmann::json& roots = b.json()["scenes"][0]["nodes"];
    for (int i = 1; i < 100000; ++i) {
        nodes.push_back({{"mesh", 0}, {"translation", {i % 100, 0, i / 100}}});
        roots.push_back(i);
    }
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    EXPECT_EQ(loaded.scene.objects.size(), 100000u);
    EXPECT_EQ(loaded.scene.meshes.size(), 1u);
}

TEST_F(GltfLoaderTest, JsonNestedTooDeeplyIsRefused)
{
    GltfBuilder b = cubeScene();
    nlohmann::json deep = nlohmann::json::array();
    for (int i = 0; i < 200; ++i)
        deep = nlohmann::json::array({deep});
    b.json()["extras"] = deep;
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: cannot read: JSON nested deeper than 128 levels");
}

TEST_F(GltfLoaderTest, DeepNodeChainsAreRefused)
{
    GltfBuilder b = cubeScene();
    for (int i = 1; i <= 1001; ++i) {
        b.json()["nodes"][std::size_t(i - 1)]["children"] = {i};
        b.json()["nodes"].push_back(nlohmann::json::object());
    }
    EXPECT_CONTAINS(errorOf(write(b)), "levels deep, over the limit of 1000");
}

// Bad files: one GltfError naming the file and what is wrong.

TEST_F(GltfLoaderTest, MissingFile) { EXPECT_CONTAINS(errorOf(folder_ / "absent.gltf"), "absent.gltf: no such file"); }

TEST_F(GltfLoaderTest, MissingBuffer)
{
    const GltfBuilder b = cubeScene();
    b.writeGltf(folder_ / "scene.gltf", true);
    std::filesystem::remove(folder_ / "scene.bin");
    const std::string message = errorOf(folder_ / "scene.gltf");
    EXPECT_CONTAINS(message, "scene.gltf: cannot read");
    EXPECT_CONTAINS(message, "scene.bin");
}

TEST_F(GltfLoaderTest, WrongAccessorType)
{
    GltfBuilder b = cubeScene();
    nlohmann::json& accessor = b.json()["accessors"][std::size_t(attribute(b, "POSITION"))];
    accessor["type"] = "VEC2";
    accessor["min"] = {-1.0, -1.0};
    accessor["max"] = {1.0, 1.0};
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /meshes/0/primitives/0/attributes/POSITION: accessor 0 is VEC2 of "
                                       "component type 5126, which POSITION may not use");
}

TEST_F(GltfLoaderTest, WrongComponentType)
{
    GltfBuilder b = cubeScene();
    b.json()["accessors"][primitive(b)["indices"].get<std::size_t>()]["componentType"] = 5126;
    EXPECT_CONTAINS(errorOf(write(b)), "/meshes/0/primitives/0/indices: accessor 3 is not a SCALAR of UNSIGNED_BYTE, "
                                       "UNSIGNED_SHORT or UNSIGNED_INT");
}

// Found by the gltf fuzz target: a component type beyond int64 was converted to int64 before it was compared
// (undefined behaviour); it is refused as any other value that is not a component type.
TEST_F(GltfLoaderTest, ComponentTypeBeyondInt64IsRefused)
{
    GltfBuilder b = cubeScene();
    b.json()["accessors"][0]["componentType"] = 8.88889e35;
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /accessors/0/componentType: expected one of 5120, 5121, 5122, "
                                       "5123, 5125, 5126, got 8.88889e+35");
}

TEST_F(GltfLoaderTest, IndexPastTheVertices)
{
    GltfBuilder b;
    const std::vector<glm::vec3> positions(24, glm::vec3(0.0f));
    std::vector<std::uint32_t> indices(36, 0u);
    indices[7] = 40;
    const int mesh = b.add("meshes", {{"name", "Cube"},
                                      {"primitives",
                                       {{{"attributes", {{"POSITION", b.addPositions(positions)}}},
                                         {"indices", b.addIndices(indices, Component::UnsignedShort)}}}}});
    b.addRoot(b.add("nodes", {{"mesh", mesh}}));
    EXPECT_CONTAINS(
        errorOf(write(b)),
        "scene.gltf: mesh 0 ('Cube') primitive 0: accessor 1 (indices) refers to vertex 40 but POSITION has 24");
}

TEST_F(GltfLoaderTest, AccessorPastTheBufferViewEnd)
{
    GltfBuilder b = cubeScene();
    for (const char* semantic : {"POSITION", "NORMAL", "TEXCOORD_0"})
        b.json()["accessors"][std::size_t(attribute(b, semantic))]["count"] = 25;
    EXPECT_CONTAINS(errorOf(write(b)),
                    "/accessors/0/count: 25 elements need 300 bytes of buffer view 0, which has 288");
}

TEST_F(GltfLoaderTest, BufferViewPastTheBufferEnd)
{
    GltfBuilder b = cubeScene();
    b.json()["bufferViews"][0]["byteLength"] = 100000;
    EXPECT_CONTAINS(errorOf(write(b)),
                    "/bufferViews/0/byteLength: the view ends at byte 100000, past the end of buffer 0");
}

TEST_F(GltfLoaderTest, AttributeCountsDiffer)
{
    GltfBuilder b = cubeScene();
    const std::vector<glm::vec2> uvs(3, glm::vec2(0.0f));
    primitive(b)["attributes"]["TEXCOORD_0"] = b.addUvs(uvs);
    EXPECT_CONTAINS(errorOf(write(b)),
                    "/meshes/0/primitives/0/attributes/TEXCOORD_0: accessor 4 has 3 elements, other attributes 24");
}

TEST_F(GltfLoaderTest, TruncatedGlb)
{
    const std::vector<std::uint8_t> bytes = cubeScene().glbBytes();
    const std::filesystem::path path = folder_ / "truncated.glb";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size() / 2));
    EXPECT_CONTAINS(errorOf(path), "truncated.glb: GLB: the header says");
}

TEST_F(GltfLoaderTest, UnsupportedPrimitiveMode)
{
    GltfBuilder b = cubeScene();
    primitive(b)["mode"] = 1;
    EXPECT_CONTAINS(errorOf(write(b)),
                    "scene.gltf: mesh 0 ('Cube') primitive 0: mode LINES is not supported, only TRIANGLES");
}

TEST_F(GltfLoaderTest, NodeThatIsItsOwnAncestor)
{
    GltfBuilder b = cubeScene();
    b.json()["nodes"][0]["children"] = {0};
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /nodes/0: the node is its own ancestor");
}

TEST_F(GltfLoaderTest, BadLightValuesAreReportedWithTheFile)
{
    GltfBuilder b = testing::exampleScene();
    b.json()["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] =
        0.6; // beyond the outer angle
    EXPECT_CONTAINS(
        errorOf(write(b)),
        "scene.gltf: /extensions/KHR_lights_punctual/lights/1/spot/innerConeAngle: 0.6 is not below outerConeAngle 0.5");
}

TEST_F(GltfLoaderTest, ALightsExtrasSetItsStaticMapMode)
{
    GltfBuilder b = testing::exampleScene();
    auto& lights = b.json()["extensions"]["KHR_lights_punctual"]["lights"];
    lights[0]["extras"]["shadowUpdate"] = "onDemand";
    lights[2]["extras"]["shadowUpdate"] = "everyFrame";
    const Scene scene = gltf::loadGltf(write(b)).scene;
    EXPECT_EQ(scene.lights[0].shadowUpdate, StaticShadowUpdate::OnDemand);
    EXPECT_EQ(scene.spotLights[0].shadowUpdate, std::nullopt);
    EXPECT_EQ(scene.pointLights[0].shadowUpdate, StaticShadowUpdate::EveryFrame);
    lights[1]["extras"]["shadowUpdate"] = "sometimes";
    EXPECT_CONTAINS(errorOf(write(b)),
                    "light 1 ('spot'): extras.shadowUpdate is not one of settings, everyFrame, onChange, onDemand");
}

TEST_F(GltfLoaderTest, ALightsExtrasSetItsShadowResolution)
{
    GltfBuilder b = testing::exampleScene();
    auto& lights = b.json()["extensions"]["KHR_lights_punctual"]["lights"];
    lights[1]["extras"]["shadowResolution"] = 512;
    const Scene scene = gltf::loadGltf(write(b)).scene;
    EXPECT_EQ(scene.spotLights[0].shadowResolution, std::optional<float>(512.0f));
    EXPECT_EQ(scene.pointLights[0].shadowResolution, std::nullopt);
    lights[1]["extras"]["shadowResolution"] = "high";
    EXPECT_CONTAINS(errorOf(write(b)), "light 1 ('spot'): extras.shadowResolution is not a number");
}

} // namespace
} // namespace penumbra::scene
