// The loader's side of glTF materials as authored: factors, textures with their uv set and KHR_texture_transform,
// doubleSided, KHR_materials_unlit and _emissive_strength, COLOR_0, TANGENT and computed tangents, the notes for
// what is not supported, and bad values named with their field and range.
#include "GltfLoaderFixture.hpp"

#include <glm/geometric.hpp>

#include <array>

namespace penumbra::scene {
namespace {

using Texel = std::array<std::uint8_t, 4>;

// One quad (testing::addQuadMesh) with material `material` under one root node.
GltfBuilder quadScene(const nlohmann::json& material, const testing::QuadAttributes& attributes = {})
{
    GltfBuilder b;
    const int index = b.add("materials", material);
    b.addRoot(b.add("nodes", {{"name", "quad"}, {"mesh", testing::addQuadMesh(b, "quad", index, attributes)}}));
    return b;
}

const std::array<Texel, 1> kGrey{{{128, 128, 128, 255}}};

TEST_F(GltfLoaderTest, MaterialFactorsTexturesAndExtensionsAreRead)
{
    GltfBuilder b;
    const int texture = testing::addTextureRow(b, kGrey);
    const nlohmann::json transform = {{"offset", {0.25, 0.5}}, {"rotation", 0.5}, {"scale", {2.0, 3.0}}};
    const int material = b.add(
        "materials",
        {{"name", "all"},
         {"doubleSided", true},
         {"pbrMetallicRoughness",
          {{"metallicFactor", 0.25},
           {"roughnessFactor", 0.75},
           {"baseColorTexture", {{"index", texture}, {"texCoord", 1}}},
           {"metallicRoughnessTexture", {{"index", texture}, {"extensions", {{"KHR_texture_transform", transform}}}}}}},
         {"normalTexture", {{"index", texture}, {"scale", 0.5}}},
         {"occlusionTexture", {{"index", texture}, {"strength", 0.3}}},
         {"emissiveTexture", {{"index", texture}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}},
         {"emissiveFactor", {0.5, 0.25, 1.0}},
         {"extensions",
          {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}},
           {"KHR_materials_unlit", nlohmann::json::object()}}}});
    b.addRoot(b.add("nodes", {{"mesh", testing::addQuadMesh(b, "quad", material, {.mirroredUv1 = true})}}));
    b.json()["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_unlit"};
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    for (const std::string& note : loaded.notes)
        EXPECT_EQ(note.find("extension"), std::string::npos) << "a supported extension is noted: " << note;
    const Material& m = loaded.scene.materials.at(loaded.scene.objects[0].material);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_TRUE(m.unlit);
    EXPECT_FALSE(m.blend);
    EXPECT_FLOAT_EQ(m.metallic, 0.25f);
    EXPECT_FLOAT_EQ(m.roughness, 0.75f);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.3f);
    EXPECT_EQ(m.emissive, glm::vec3(2.0f, 1.0f, 4.0f));
    for (const std::optional<MaterialTexture>& t : m.textures)
        ASSERT_TRUE(t.has_value());
    // One glTF texture, decoded once per colour space: base colour and emissive read it as sRGB colour, the
    // other slots as linear data.
    ASSERT_EQ(loaded.scene.textures.size(), 2u) << "one scene texture per colour space";
    const std::uint32_t srgb = m.texture(TextureSlot::BaseColor)->image;
    EXPECT_EQ(loaded.scene.textures.at(srgb).colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(m.texture(TextureSlot::Emissive)->image, srgb);
    const std::uint32_t linear = m.texture(TextureSlot::MetallicRoughness)->image;
    EXPECT_NE(linear, srgb);
    EXPECT_EQ(loaded.scene.textures.at(linear).colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(m.texture(TextureSlot::Normal)->image, linear);
    EXPECT_EQ(m.texture(TextureSlot::Occlusion)->image, linear);
    EXPECT_EQ(m.texture(TextureSlot::BaseColor)->texCoord, 1u);
    EXPECT_EQ(m.texture(TextureSlot::Emissive)->texCoord, 1u) << "KHR_texture_transform's texCoord overrides";
    const TextureTransform& moved = m.texture(TextureSlot::MetallicRoughness)->transform;
    EXPECT_EQ(moved.offset, glm::vec2(0.25f, 0.5f));
    EXPECT_FLOAT_EQ(moved.rotation, 0.5f);
    EXPECT_EQ(moved.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(m.texture(TextureSlot::Normal)->transform.scale, glm::vec2(1.0f));
}

TEST_F(GltfLoaderTest, TextureTransformMatrixRotatesAsTheSampleModelsDo)
{
    // KHR_texture_transform with the rotation of glTF issue 1563 (what the sample model TextureTransformTest and
    // its implementations show): a quarter turn takes uv (1, 0) to (0, -1) and (0, 1) to (1, 0).
    const TextureTransform quarter{.offset = glm::vec2(0.5f, 0.25f), .rotation = 1.5707963f, .scale = glm::vec2(2.0f)};
    const glm::mat3 m = quarter.matrix();
    const glm::vec3 u = m * glm::vec3(1.0f, 0.0f, 1.0f);
    const glm::vec3 v = m * glm::vec3(0.0f, 1.0f, 1.0f);
    EXPECT_NEAR(u.x, 0.5f, 1e-5f);
    EXPECT_NEAR(u.y, 0.25f - 2.0f, 1e-5f);
    EXPECT_NEAR(v.x, 0.5f + 2.0f, 1e-5f);
    EXPECT_NEAR(v.y, 0.25f, 1e-5f);
}

TEST_F(GltfLoaderTest, VertexColoursOfEveryStorageAreRead)
{
    const GltfBuilder bytes = quadScene({{"name", "rgb"}}, {.color = glm::vec4(0.2f, 0.6f, 1.0f, 1.0f)});
    const MeshData rgb = gltf::loadGltf(write(bytes, "rgb.gltf")).scene.meshes.at(0);
    for (const Vertex& v : rgb.vertices) {
        EXPECT_NEAR(v.color.r, 51.0f / 255.0f, 1e-6f);
        EXPECT_NEAR(v.color.g, 153.0f / 255.0f, 1e-6f);
        EXPECT_EQ(v.color.a, 1.0f) << "VEC3 colours are opaque";
    }
    const GltfBuilder floats = quadScene({{"name", "rgba"}}, {.color = glm::vec4(0.2f, 0.6f, 1.0f, 0.5f)});
    EXPECT_EQ(gltf::loadGltf(write(floats, "rgba.gltf")).scene.meshes.at(0).vertices[2].color,
              glm::vec4(0.2f, 0.6f, 1.0f, 0.5f));
    const GltfBuilder none = quadScene({{"name", "plain"}});
    EXPECT_EQ(gltf::loadGltf(write(none, "none.gltf")).scene.meshes.at(0).vertices[0].color, glm::vec4(1.0f));
}

TEST_F(GltfLoaderTest, TangentsAreReadOrComputedForNormalTextures)
{
    GltfBuilder b;
    const int texture = testing::addTextureRow(b, kGrey);
    const nlohmann::json bumpy = {{"name", "bumpy"}, {"normalTexture", {{"index", texture}}}};
    const int withTangents =
        testing::addQuadMesh(b, "given", b.add("materials", bumpy), {.tangent = glm::vec4(0.0f, 1.0f, 0.0f, -1.0f)});
    const int computed = testing::addQuadMesh(b, "computed", 0);
    b.addRoot(b.add("nodes", {{"mesh", withTangents}}));
    b.addRoot(b.add("nodes", {{"mesh", computed}}));
    const Scene scene = gltf::loadGltf(write(b)).scene;
    EXPECT_EQ(scene.meshes.at(0).vertices[0].tangent, glm::vec4(0.0f, 1.0f, 0.0f, -1.0f)) << "TANGENT as written";
    // u runs along +x and v down the image along -y: the tangent is +x, and the bitangent cross(n, t) = +y points up
    // the image, as a normal texture's +Y does, so w = +1.
    for (const Vertex& v : scene.meshes.at(1).vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
}

TEST_F(GltfLoaderTest, ComputedTangentsFollowTheNormalTexturesUvSetAndMirroring)
{
    GltfBuilder b;
    const int texture = testing::addTextureRow(b, kGrey);
    // TEXCOORD_1 runs u the other way (along -x): the tangent is -x, and the bitangent stays +y, so w = -1.
    const int material =
        b.add("materials", {{"name", "uv1"}, {"normalTexture", {{"index", texture}, {"texCoord", 1}}}});
    b.addRoot(b.add("nodes", {{"mesh", testing::addQuadMesh(b, "quad", material, {.mirroredUv1 = true})}}));
    const Scene scene = gltf::loadGltf(write(b)).scene;
    for (const Vertex& v : scene.meshes.at(0).vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(-1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST_F(GltfLoaderTest, BlendMaterialsAreBlendedAndDitherCast)
{
    const GltfBuilder b = quadScene({{"name", "glass"}, {"alphaMode", "BLEND"}});
    const Material m = gltf::loadGltf(write(b)).scene.materials.at(0);
    EXPECT_TRUE(m.blend);
    EXPECT_EQ(m.caster, CasterMode::Dither);
    EXPECT_FALSE(m.doubleSided);
}

TEST_F(GltfLoaderTest, UnsupportedFeaturesAreNamedOncePerFile)
{
    GltfBuilder b = quadScene({{"name", "plain"}});
    b.json()["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    std::string all;
    for (const std::string& note : loaded.notes)
        all += note + "\n";
    EXPECT_EQ(all, "extension KHR_materials_clearcoat is not supported: ignored\n"
                   "no camera: framing the scene's bounds\n"
                   "no lights: added a default sun with shadows, 45 degrees up over the camera's left shoulder\n");
}

TEST_F(GltfLoaderTest, BadMaterialValuesAreNamedWithTheirField)
{
    GltfBuilder b;
    const int texture = testing::addTextureRow(b, kGrey);
    const auto errorFor = [&](const nlohmann::json& material) {
        GltfBuilder copy = b;
        copy.json()["materials"] = {material};
        copy.json()["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_texture_transform"};
        copy.addRoot(copy.add("nodes", {{"mesh", testing::addQuadMesh(copy, "quad", 0, {.mirroredUv1 = true})}}));
        return errorOf(write(copy));
    };
    EXPECT_CONTAINS(
        errorFor({{"name", "m"}, {"normalTexture", {{"index", texture}, {"texCoord", 2}}}}),
        "scene.gltf: /meshes/0/primitives/0/material: material 0 reads TEXCOORD_2, which the primitive lacks");
    EXPECT_CONTAINS(
        errorFor({{"pbrMetallicRoughness", {{"metallicFactor", 1.5}}}}),
        "scene.gltf: /materials/0/pbrMetallicRoughness/metallicFactor: expected a number in [0, 1], got 1.5");
    EXPECT_CONTAINS(errorFor({{"occlusionTexture", {{"index", texture}, {"strength", -1}}}}),
                    "/materials/0/occlusionTexture/strength: expected a number in [0, 1], got -1");
    EXPECT_CONTAINS(
        errorFor({{"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", -2}}}}}}),
        "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength: expected a number in [0, inf], got -2");
    EXPECT_CONTAINS(
        errorFor({{"emissiveTexture",
                   {{"index", texture}, {"extensions", {{"KHR_texture_transform", {{"offset", {1, 2, 3}}}}}}}}}),
        "/materials/0/emissiveTexture/extensions/KHR_texture_transform/offset: expected an array of 2 numbers, got [1,2,3]");
    EXPECT_CONTAINS(
        errorFor({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 7}}}}}}),
        "/materials/0/pbrMetallicRoughness/baseColorTexture/index: expected an index of textures (the file has 1), got 7");
}

} // namespace
} // namespace penumbra::scene
