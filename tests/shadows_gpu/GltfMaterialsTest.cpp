// glTF materials as authored, through the lit and caster passes of every configuration: each feature in a file the
// test support writes, its lit picture read back and checked for what the feature must change.
#include "GltfBuilder.hpp"
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/render/SceneRenderer.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kMaterialsWidth = 320;
constexpr std::uint32_t kMaterialsHeight = 180;
using Texel = std::array<std::uint8_t, 4>;

// Points on the quad of quadFile(): on its left half and on its right half, each between two texels of halves().
constexpr glm::vec3 kLeft{-0.5f, 0.0f, 0.0f};
constexpr glm::vec3 kRight{0.5f, 0.0f, 0.0f};
constexpr glm::vec3 kCentre{0.0f, 0.0f, 0.0f};

// A row of 4 texels, 2 for each half of the quad, so the linear filter at kLeft and kRight reads one value.
int halves(GltfBuilder& b, Texel left, Texel right)
{
    const std::array<Texel, 4> texels{left, left, right, right};
    return addTextureRow(b, texels);
}

// One quad at the origin facing +z with `material`, turned by `yaw` radians about y.
GltfBuilder quadFile(const nlohmann::json& material, const QuadAttributes& attributes = {}, float yaw = 0.0f)
{
    GltfBuilder b;
    const int index = b.add("materials", material);
    b.addRoot(b.add("nodes", {{"name", "quad"},
                              {"mesh", addQuadMesh(b, "quad", index, attributes)},
                              {"rotation", {0.0, std::sin(0.5 * yaw), 0.0, std::cos(0.5 * yaw)}}}));
    return b;
}

// `b`, a quadFile(), with its quad made 1 x 1 and lifted 1.5 above a ground plane, facing down (`facingDown`) or up.
GltfBuilder casterFile(GltfBuilder b, bool facingDown)
{
    const int ground = b.add("materials", {{"name", "ground"}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
    b.addRoot(b.add("nodes", {{"name", "ground"},
                              {"mesh", addCubeMesh(b, "ground", ground)},
                              {"translation", {0, -0.1, 0}},
                              {"scale", {6, 0.1, 6}}}));
    const double half = 0.7071068 * (facingDown ? 1.0 : -1.0); // about x: +z turns to -y (down) or +y (up)
    b.json()["nodes"][0]["translation"] = {0, 1.5, 0};
    b.json()["nodes"][0]["rotation"] = {half, 0, 0, 0.7071068};
    b.json()["nodes"][0]["scale"] = {0.5, 0.5, 0.5};
    return b;
}

// Where the casterFile quad's shadow falls with the sun of casterScene (the sun leans towards +x).
constexpr glm::vec3 kShadowedGround{1.1f, 0.0f, 0.0f};

// `b` with every extension its objects use listed in extensionsUsed, as glTF 2.0 section 3.12 requires (the loader
// refuses a file that uses one without declaring it).
GltfBuilder declaringExtensions(GltfBuilder b)
{
    std::set<std::string> used;
    const std::function<void(const nlohmann::json&)> visit = [&](const nlohmann::json& j) {
        if (j.is_array())
            for (const nlohmann::json& item : j)
                visit(item);
        if (!j.is_object())
            return;
        for (const auto& [key, value] : j.items()) {
            if (key == "extensions" && value.is_object())
                for (const auto& [name, unused] : value.items())
                    used.insert(name);
            visit(value);
        }
    };
    visit(b.json());
    if (!used.empty())
        b.json()["extensionsUsed"] = std::vector<std::string>(used.begin(), used.end());
    return b;
}

class GltfMaterialsTest : public GpuTest {
protected:
    // The file as the loader reads it, lit by one sun along `direction` (intensity 0: unlit but for ambient and
    // emission) and seen from (0, 0, 3).
    scene::Scene load(const GltfBuilder& b, glm::vec3 direction = {0.0f, 0.0f, -1.0f}, float intensity = 2.0f)
    {
        const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                           ("penumbra-materials-" + configuration() + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".glb");
        declaringExtensions(b).writeGlb(path);
        scene::Scene scene = gltf::loadGltf(path).scene;
        std::filesystem::remove(path);
        scene.lights = {{.name = "sun", .intensity = intensity, .direction = glm::normalize(direction)}};
        scene.camera = scene::lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 0.9f);
        return scene;
    }

    // A casterFile scene: the sun from above, leaning towards +x, the camera in front, looking down at the shadow.
    scene::Scene casterScene(const GltfBuilder& b)
    {
        scene::Scene scene = load(b, {0.6f, -1.0f, 0.0f});
        scene.camera = scene::lookAt({0.0f, 4.0f, 5.0f}, {0.6f, 0.5f, 0.0f}, 0.9f);
        return scene;
    }

    rhi::Image render(const scene::Scene& scene, render::AmbientLight ambient = {})
    {
        render::FrameDesc frame;
        frame.width = kMaterialsWidth;
        frame.height = kMaterialsHeight;
        frame.ambient = ambient;
        return renderLit(*device, scene, frame);
    }

    Rgba at(const rhi::Image& image, const scene::Scene& scene, glm::vec3 world) const
    {
        const glm::uvec2 p = pixelOf(*device, scene.camera, kMaterialsWidth, kMaterialsHeight, world);
        return pixel(image, p.x, p.y);
    }

    float luma(const rhi::Image& image, const scene::Scene& scene, glm::vec3 world) const
    {
        const glm::uvec2 p = pixelOf(*device, scene.camera, kMaterialsWidth, kMaterialsHeight, world);
        return luminance(image, p.x, p.y);
    }

    // On failure, the pictures' paths.
    void keep(std::initializer_list<std::pair<const char*, const rhi::Image*>> pictures)
    {
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::string paths;
        for (const auto& [name, image] : pictures)
            paths += savePicture(*image, "materials-" + test + "-" + configuration() + "-" + name) + " ";
        if (HasFailure())
            ADD_FAILURE() << "pictures: " << paths;
    }
};

TEST_F(GltfMaterialsTest, DoubleSidedQuadSeenFromBehindIsDrawnAndLitWhileASingleSidedOneIsCulled)
{
    // Turned half round: the camera (and the sun, shining from the camera's side) see the quads' back faces.
    const nlohmann::json red = {
        {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.2, 1.0}}, {"metallicFactor", 0.0}}}};
    nlohmann::json twoSided = red;
    twoSided["doubleSided"] = true;
    const scene::Scene single = load(quadFile(red, {}, 3.14159265f));
    const scene::Scene both = load(quadFile(twoSided, {}, 3.14159265f));
    const rhi::Image culled = render(single);
    const rhi::Image drawn = render(both);
    const Rgba back = at(drawn, both, kCentre);
    std::printf("[ materials ] %s: single-sided back %s, double-sided back %s\n", configuration().c_str(),
                describe(at(culled, single, kCentre)).c_str(), describe(back).c_str());
    EXPECT_EQ(at(culled, single, kCentre), (Rgba{51, 56, 66, 255})) << "a single-sided back face is drawn";
    // Lit with the flipped normal it faces the sun (n.l = 1); with the unflipped one only the ambient term is left.
    EXPECT_GT(back[0], 150) << "the double-sided back face is not drawn, or not lit from its side";
    EXPECT_GT(back[0], back[1] + 60);
    keep({{"single", &culled}, {"double", &drawn}});
}

TEST_F(GltfMaterialsTest, DoubleSidedCastersCastFromTheirBackFace)
{
    // The quad faces the ground: the sun sees its back face, which a single-sided caster culls.
    const nlohmann::json grey = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
    nlohmann::json twoSided = grey;
    twoSided["doubleSided"] = true;
    const scene::Scene single = casterScene(casterFile(quadFile(grey), true));
    const scene::Scene both = casterScene(casterFile(quadFile(twoSided), true));
    const rhi::Image withoutShadow = render(single);
    const rhi::Image withShadow = render(both);
    const float lit = luma(withoutShadow, single, kShadowedGround);
    const float shadowed = luma(withShadow, both, kShadowedGround);
    std::printf("[ materials ] %s: ground under a single-sided quad %.1f, under a double-sided one %.1f\n",
                configuration().c_str(), lit, shadowed);
    EXPECT_GT(lit, 150.0f) << "the single-sided quad's back face casts";
    EXPECT_LT(shadowed, 0.5f * lit) << "the double-sided quad's back face casts no shadow";
    keep({{"single", &withoutShadow}, {"double", &withShadow}});
}

TEST_F(GltfMaterialsTest, VertexColoursMultiplyTheBaseColour)
{
    const nlohmann::json white = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
    const scene::Scene coloured = load(quadFile(white, {.color = glm::vec4(0.1f, 0.9f, 0.1f, 1.0f)}));
    const scene::Scene plain = load(quadFile(white));
    const rhi::Image withColours = render(coloured);
    const rhi::Image without = render(plain);
    const Rgba c = at(withColours, coloured, kCentre);
    const Rgba p = at(without, plain, kCentre);
    std::printf("[ materials ] %s: with COLOR_0 %s, without %s\n", configuration().c_str(), describe(c).c_str(),
                describe(p).c_str());
    EXPECT_GT(c[1], 2 * c[0]) << "COLOR_0's green does not reach the surface";
    EXPECT_GT(c[1], 2 * c[2]);
    EXPECT_NEAR(p[0], p[1], 2) << "a white material without COLOR_0 is not neutral";
    keep({{"colours", &withColours}, {"plain", &without}});
}

TEST_F(GltfMaterialsTest, MetallicRoughnessTextureMultipliesTheFactors)
{
    // Left: dielectric (B = 0); right: metal (B = 255); both fully rough (G = 255). Lit head-on, a rough metal has no
    // diffuse term and reflects little; the dielectric is bright.
    const auto file = [](double metallicFactor) {
        GltfBuilder b;
        const int texture = halves(b, {0, 255, 0, 255}, {0, 255, 255, 255});
        b.add("materials", {{"pbrMetallicRoughness",
                             {{"baseColorFactor", {0.9, 0.9, 0.9, 1.0}},
                              {"metallicFactor", metallicFactor},
                              {"metallicRoughnessTexture", {{"index", texture}}}}}});
        b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0)}}));
        return b;
    };
    const scene::Scene textured = load(file(1.0));
    const scene::Scene dielectric = load(file(0.0));
    const rhi::Image metalRight = render(textured);
    const rhi::Image noMetal = render(dielectric);
    const float left = luma(metalRight, textured, kLeft), right = luma(metalRight, textured, kRight);
    std::printf("[ materials ] %s: dielectric half %.1f, metal half %.1f; metallicFactor 0: %.1f, %.1f\n",
                configuration().c_str(), left, right, luma(noMetal, dielectric, kLeft),
                luma(noMetal, dielectric, kRight));
    EXPECT_GT(left, 1.5f * right) << "the texture's blue channel does not make the right half metal";
    EXPECT_NEAR(luma(noMetal, dielectric, kLeft), luma(noMetal, dielectric, kRight), 2.0f)
        << "metallicFactor 0 does not scale the texture's metal away";
    keep({{"metal-right", &metalRight}, {"factor-0", &noMetal}});
}

// Left: the normal tilted towards the tangent (+u, world +x); right: towards the bitangent (up the image, world +y).
// The sun comes from +x, +y and +z, so both tilts face it more than the flat quad does (n.l 0.81 against 0.58); a
// tangent or bitangent of the wrong sign would face them away (0.12).
TEST_F(GltfMaterialsTest, NormalTextureTiltsTheShadingWithAndWithoutTangents)
{
    const auto file = [](bool normalTexture, std::optional<glm::vec4> tangent) {
        GltfBuilder b;
        nlohmann::json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
        if (normalTexture)
            material["normalTexture"] = {{"index", halves(b, {204, 128, 230, 255}, {128, 204, 230, 255})}};
        b.add("materials", material);
        b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0, {.tangent = tangent})}}));
        return b;
    };
    const glm::vec3 sun{-1.0f, -1.0f, -1.0f};
    const scene::Scene flat = load(file(false, std::nullopt), sun);
    const scene::Scene given = load(file(true, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)), sun);
    const scene::Scene computed = load(file(true, std::nullopt), sun);
    const rhi::Image flatImage = render(flat), givenImage = render(given), computedImage = render(computed);
    for (const glm::vec3 point : {kLeft, kRight}) {
        const float f = luma(flatImage, flat, point), g = luma(givenImage, given, point),
                    c = luma(computedImage, computed, point);
        std::printf("[ materials ] %s: at x = %.1f flat %.1f, with TANGENT %.1f, computed tangents %.1f\n",
                    configuration().c_str(), point.x, f, g, c);
        EXPECT_GT(g, f + 15.0f) << "the normal texture does not tilt the normal towards the sun (TANGENT)";
        EXPECT_GT(c, f + 15.0f) << "the normal texture does not tilt the normal towards the sun (computed)";
        EXPECT_NEAR(c, g, 1.0f) << "computed tangents differ from the file's for a plain quad";
    }
    keep({{"flat", &flatImage}, {"given", &givenImage}, {"computed", &computedImage}});
}

TEST_F(GltfMaterialsTest, EmissiveFactorTextureAndStrengthAddLight)
{
    // No light, no ambient: only emission shows. The texture lets the left half glow and keeps the right half dark.
    const auto file = [](std::optional<double> strength) {
        GltfBuilder b;
        nlohmann::json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
                                   {"emissiveFactor", {0.1, 0.4, 0.6}},
                                   {"emissiveTexture", {{"index", halves(b, {255, 255, 255, 255}, {0, 0, 0, 255})}}}};
        if (strength)
            material["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", *strength}};
        b.add("materials", material);
        b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0)}}));
        return b;
    };
    const scene::Scene plain = load(file(std::nullopt), {0, 0, -1}, 0.0f);
    const scene::Scene strong = load(file(1.5), {0, 0, -1}, 0.0f);
    const rhi::Image plainImage = render(plain, {.intensity = 0.0f}), strongImage = render(strong, {.intensity = 0.0f});
    const Rgba glow = at(plainImage, plain, kLeft), brighter = at(strongImage, strong, kLeft);
    std::printf("[ materials ] %s: emissive %s, with strength 1.5 %s, masked half %s\n", configuration().c_str(),
                describe(glow).c_str(), describe(brighter).c_str(), describe(at(plainImage, plain, kRight)).c_str());
    // sRGB of linear 0.4 and 0.6: 170 and 203; times 1.5: 203 and 228.
    EXPECT_NEAR(glow[1], 170, 3);
    EXPECT_NEAR(glow[2], 203, 3);
    EXPECT_NEAR(brighter[1], 203, 3) << "KHR_materials_emissive_strength does not scale the emission";
    EXPECT_LT(luma(plainImage, plain, kRight), 2.0f) << "the emissive texture's black half glows";
    keep({{"emissive", &plainImage}, {"strength", &strongImage}});
}

TEST_F(GltfMaterialsTest, OcclusionTextureDarkensTheAmbientTermOnly)
{
    // Left unoccluded (R = 255), right fully occluded (R = 0).
    const auto file = [](double strength) {
        GltfBuilder b;
        b.add("materials",
              {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
               {"occlusionTexture", {{"index", halves(b, {255, 0, 0, 255}, {0, 0, 0, 255})}, {"strength", strength}}}});
        b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0)}}));
        return b;
    };
    const render::AmbientLight ambient{.intensity = 0.4f};
    const scene::Scene full = load(file(1.0), {0, 0, -1}, 0.0f);
    const scene::Scene half = load(file(0.5), {0, 0, -1}, 0.0f);
    const scene::Scene sunlit = load(file(1.0), {0, 0, -1}, 2.0f);
    const rhi::Image fullImage = render(full, ambient), halfImage = render(half, ambient),
                     sunlitImage = render(sunlit, ambient);
    const float open = luma(fullImage, full, kLeft), occluded = luma(fullImage, full, kRight),
                halfOccluded = luma(halfImage, half, kRight);
    std::printf(
        "[ materials ] %s: ambient only: open %.1f, occluded %.1f, at strength 0.5 %.1f; sunlit occluded %.1f\n",
        configuration().c_str(), open, occluded, halfOccluded, luma(sunlitImage, sunlit, kRight));
    EXPECT_GT(open, 150.0f);
    EXPECT_LT(occluded, 2.0f) << "occlusion 0 leaves ambient light";
    // Linear 0.4 x 0.5 = 0.2: sRGB 124.
    EXPECT_NEAR(halfOccluded, 124.0f, 3.0f) << "occlusionTexture.strength does not scale the occlusion";
    EXPECT_GT(luma(sunlitImage, sunlit, kRight), 180.0f) << "occlusion darkens direct light";
    keep({{"full", &fullImage}, {"half", &halfImage}, {"sunlit", &sunlitImage}});
}

TEST_F(GltfMaterialsTest, OcclusionTextureDarkensTheEnvironmentsDiffuseAndSpecular)
{
    // The occlusion quad of the test above in a uniform environment: occlusion 0 takes the diffuse and, through the
    // specular occlusion term (Lagarde 2014, section 4.10), the specular away; the open half keeps both.
    GltfBuilder b;
    b.add("materials", {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                        {"occlusionTexture", {{"index", halves(b, {255, 0, 0, 255}, {0, 0, 0, 255})}}}});
    b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0)}}));
    const scene::Scene scene = load(b, {0, 0, -1}, 0.0f);
    auto uniform = std::make_shared<render::EnvironmentImage>();
    uniform->width = 64;
    uniform->height = 32;
    uniform->texels.assign(64 * 32, glm::vec3(0.4f));
    render::FrameDesc frame;
    frame.width = kMaterialsWidth;
    frame.height = kMaterialsHeight;
    frame.environment.image = uniform;
    const rhi::Image image = renderLit(*device, scene, frame);
    EXPECT_GT(luma(image, scene, kLeft), 120.0f) << "the environment does not light the open half";
    EXPECT_LT(luma(image, scene, kRight), 2.0f) << "occlusion 0 leaves environment light";
    keep({{"environment", &image}});
}

TEST_F(GltfMaterialsTest, HemisphereAmbientLightsFromTheSkyAboveAndTheGroundBelow)
{
    // No light; quads tilted 60 degrees towards the sky and towards the ground (n.y = +-0.87: 93 % of one colour).
    const nlohmann::json white = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
    const render::AmbientLight hemisphere{.color = {1.0f, 0.1f, 0.1f},
                                          .intensity = 0.5f,
                                          .ground = glm::vec3(0.1f, 0.1f, 1.0f)};
    for (const double sign : {1.0, -1.0}) {
        GltfBuilder b = quadFile(white);
        b.json()["nodes"][0]["rotation"] = {-0.5 * sign, 0.0, 0.0, 0.8660254}; // about x by -+60 degrees
        const scene::Scene scene = load(b, {0, 0, -1}, 0.0f);
        const rhi::Image image = render(scene, hemisphere);
        const Rgba c = at(image, scene, kCentre);
        std::printf("[ materials ] %s: hemisphere, facing %s: %s\n", configuration().c_str(),
                    sign > 0 ? "the sky" : "the ground", describe(c).c_str());
        const int sky = c[0], ground = c[2];
        if (sign > 0) {
            EXPECT_GT(sky, ground + 80) << "a surface facing the sky does not take the sky's colour";
        } else {
            EXPECT_GT(ground, sky + 80) << "a surface facing the ground does not take the ground's colour";
        }
        keep({{sign > 0 ? "sky" : "ground", &image}});
    }
}

// Left texel red, right texel green; the transform or the second uv set swaps them.
TEST_F(GltfMaterialsTest, TextureTransformAndTexCoord1MoveTheBaseColourTexture)
{
    const auto file = [](const nlohmann::json& extra, bool mirroredUv1) {
        GltfBuilder b;
        nlohmann::json info = {{"index", halves(b, {230, 20, 20, 255}, {20, 230, 20, 255})}};
        info.update(extra);
        b.add("materials", {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"baseColorTexture", info}}}});
        b.addRoot(b.add("nodes", {{"mesh", addQuadMesh(b, "quad", 0, {.mirroredUv1 = mirroredUv1})}}));
        return b;
    };
    struct Case {
        const char* name;
        nlohmann::json extra;
        bool mirroredUv1;
        bool swapped;
    };
    const std::array<Case, 5> cases{{
        {"plain", nlohmann::json::object(), true, false},
        {"offset", {{"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.0}}}}}}}, false, true},
        // Half a turn about the uv origin, moved back by (1, 1): u -> 1 - u.
        {"rotation",
         {{"extensions", {{"KHR_texture_transform", {{"offset", {1.0, 1.0}}, {"rotation", 3.14159265}}}}}},
         false,
         true},
        {"texcoord1", {{"texCoord", 1}}, true, true},
        // The extension's texCoord overrides the textureInfo's.
        {"texcoord-override",
         {{"texCoord", 1}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 0}}}}}},
         true,
         false},
    }};
    for (const Case& c : cases) {
        const scene::Scene scene = load(file(c.extra, c.mirroredUv1));
        const rhi::Image image = render(scene);
        const Rgba left = at(image, scene, kLeft);
        std::printf("[ materials ] %s: %s: left %s\n", configuration().c_str(), c.name, describe(left).c_str());
        const int red = left[0], green = left[1];
        if (c.swapped) {
            EXPECT_GT(green, 2 * red) << c.name << ": the texture is not moved";
        } else {
            EXPECT_GT(red, 2 * green) << c.name << ": the texture is moved";
        }
        keep({{c.name, &image}});
    }
}

TEST_F(GltfMaterialsTest, UnlitSurfacesShowTheirBaseColourAndCastShadows)
{
    const nlohmann::json unlit = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.5, 0.1, 1.0}}}},
                                  {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}};
    // The sun behind the quad: a lit material would show only ambient light.
    const scene::Scene quad = load(quadFile(unlit), {0.0f, 0.0f, 1.0f});
    const rhi::Image image = render(quad);
    const Rgba c = at(image, quad, kCentre);
    std::printf("[ materials ] %s: unlit %s\n", configuration().c_str(), describe(c).c_str());
    // sRGB of (0.9, 0.5, 0.1): (243, 188, 89).
    EXPECT_NEAR(c[0], 243, 2);
    EXPECT_NEAR(c[1], 188, 2);
    EXPECT_NEAR(c[2], 89, 2);

    const scene::Scene caster = casterScene(casterFile(quadFile(unlit), false));
    const rhi::Image shadowed = render(caster);
    const rhi::Image unshadowed = render(withoutCaster(caster, "quad"));
    std::printf("[ materials ] %s: ground under the unlit quad %.1f, without its shadow %.1f\n",
                configuration().c_str(), luma(shadowed, caster, kShadowedGround),
                luma(unshadowed, caster, kShadowedGround));
    EXPECT_LT(luma(shadowed, caster, kShadowedGround), 0.5f * luma(unshadowed, caster, kShadowedGround))
        << "the unlit quad casts no shadow";
    keep({{"quad", &image}, {"shadow", &shadowed}});
}

TEST_F(GltfMaterialsTest, BlendedSurfacesAreDrawnBackToFrontOverTheOpaqueOnes)
{
    // A white opaque quad behind, a red and then a green half-transparent quad in front of it; the file lists the
    // nearest (green) first, so only sorting draws the red one first.
    GltfBuilder b;
    const auto glass = [&](double r, double g, double bl) {
        return b.add("materials", {{"alphaMode", "BLEND"},
                                   {"pbrMetallicRoughness", {{"baseColorFactor", {r, g, bl, 0.5}}}},
                                   {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}});
    };
    const int green = glass(0.0, 1.0, 0.0), red = glass(1.0, 0.0, 0.0);
    const int white = b.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}},
                                          {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}});
    b.addRoot(b.add("nodes", {{"name", "green"},
                              {"mesh", addQuadMesh(b, "green", green)},
                              {"translation", {0, 0, 1.0}},
                              {"scale", {0.3, 0.3, 1}}}));
    b.addRoot(b.add("nodes", {{"name", "red"},
                              {"mesh", addQuadMesh(b, "red", red)},
                              {"translation", {0, 0, 0.5}},
                              {"scale", {0.6, 0.6, 1}}}));
    b.addRoot(b.add("nodes", {{"name", "white"}, {"mesh", addQuadMesh(b, "white", white)}}));
    const scene::Scene scene = load(b);
    const rhi::Image image = render(scene);
    const Rgba both = at(image, scene, {0.0f, 0.0f, 1.0f});
    const Rgba redOnly = at(image, scene, {0.45f, 0.0f, 0.5f});
    std::printf("[ materials ] %s: green over red over white %s, red over white %s\n", configuration().c_str(),
                describe(both).c_str(), describe(redOnly).c_str());
    // Blended in the stored (sRGB-encoded) values: red over white (255, 128, 128), green over that (128, 191, 64).
    EXPECT_NEAR(redOnly[0], 255, 2);
    EXPECT_NEAR(redOnly[1], 128, 2) << "the red glass does not blend over the white quad";
    EXPECT_NEAR(both[0], 128, 2) << "the blended quads are not drawn back to front";
    EXPECT_NEAR(both[1], 191, 2);
    EXPECT_NEAR(both[2], 64, 2);
    keep({{"blend", &image}});
}

} // namespace
} // namespace penumbra::testing
