#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kMapSize = 64;

// A light looking down -z with an orthographic frustum of x, y in [-1, 1] and depth [0.5, 10].
class ShadowPrimitivesTest : public GpuTest {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        lightProjection = device->conventions().orthographic(-1, 1, -1, 1, 0.5f, 10.0f);
        casterVertex = device->createShader({rhi::ShaderStage::Vertex, R"(#version 450
layout(location = 0) in vec3 position;
layout(std140, binding = 0) uniform Light { mat4 viewProjection; } light;
void main() { gl_Position = light.viewProjection * vec4(position, 1.0); }
)",
                                             "caster.vert"});
        casterFragment =
            device->createShader({rhi::ShaderStage::Fragment, "#version 450\nvoid main() {}\n", "caster.frag"});
        lightUniforms = device->createBuffer({.size = sizeof(glm::mat4), .usage = rhi::BufferUsage::Uniform});
        lightUniforms->writeObject(lightProjection);
    }

    std::unique_ptr<rhi::Pipeline> casterPipeline(const rhi::DepthBias& bias = {})
    {
        return device->createPipeline({
            .vertex = casterVertex.get(),
            .fragment = casterFragment.get(),
            .vertexLayout = {.buffers = {{.stride = sizeof(glm::vec3)}},
                             .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3}}},
            .depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer, .bias = bias},
            .depthFormat = rhi::Format::D32F,
            .debugName = "caster",
        });
    }

    std::unique_ptr<rhi::Texture> shadowMap()
    {
        return device->createTexture({.width = kMapSize,
                                      .height = kMapSize,
                                      .format = rhi::Format::D32F,
                                      .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                      .debugName = "shadow map"});
    }

    // Depth-only pass of a triangle list into `map`; `overrideBias` goes through setDepthBias.
    void renderCasters(const rhi::Texture& map, const rhi::Pipeline& pipeline, const std::vector<glm::vec3>& triangles,
                       std::optional<rhi::DepthBias> overrideBias = {})
    {
        auto vertices =
            device->createBuffer({.size = triangles.size() * sizeof(glm::vec3), .usage = rhi::BufferUsage::Vertex});
        vertices->write(0, std::as_bytes(std::span(triangles)));
        auto framebuffer = device->createFramebuffer({.depth = {&map, 0}, .debugName = "shadow map"});
        auto commands = device->createCommandList();
        commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = std::nullopt});
        commands->bindPipeline(pipeline);
        if (overrideBias)
            commands->setDepthBias(*overrideBias);
        commands->bindUniformBuffer(0, *lightUniforms, 0, sizeof(glm::mat4));
        commands->bindVertexBuffer(0, *vertices);
        commands->draw(std::uint32_t(triangles.size()));
        commands->endPass();
        device->submit(*commands);
    }

    static std::vector<glm::vec3> quad(glm::vec2 min, glm::vec2 max, float zLeft, float zRight)
    {
        const glm::vec3 a(min.x, min.y, zLeft), b(max.x, min.y, zRight), c(max.x, max.y, zRight),
            d(min.x, max.y, zLeft);
        return {a, b, c, a, c, d};
    }

    glm::mat4 lightProjection{1.0f};
    std::unique_ptr<rhi::Shader> casterVertex, casterFragment;
    std::unique_ptr<rhi::Buffer> lightUniforms;
};

TEST_F(ShadowPrimitivesTest, ComparisonLookupGivesTheShadowMask)
{
    auto map = shadowMap();
    auto caster = casterPipeline();
    renderCasters(*map, *caster, quad({-1, -1}, {0, 1}, -2.0f, -2.0f)); // occludes the left half

    // Receiver: the plane z = -5 seen straight down the light; each pixel looks itself up.
    auto vertex = device->createShader(shaders::load("fullscreen.vert"));
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, R"(#version 450
layout(location = 0) in vec2 vNdc;
layout(std140, binding = 0) uniform Receiver { mat4 worldToShadow; } receiver;
layout(binding = 1) uniform sampler2DShadow shadowMap;
layout(location = 0) out vec4 outColor;
void main() {
    vec4 coord = receiver.worldToShadow * vec4(vNdc, -5.0, 1.0);
    outColor = vec4(vec3(texture(shadowMap, coord.xyz / coord.w)), 1.0);
}
)",
                                          "receiver.frag"});
    auto pipeline = device->createPipeline(
        {.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{.format = rhi::Format::RGBA8}}});
    auto uniforms = device->createBuffer({.size = sizeof(glm::mat4), .usage = rhi::BufferUsage::Uniform});
    uniforms->writeObject(device->conventions().clipToTexture() * lightProjection);
    auto sampler = device->createSampler(
        {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .compare = true, .debugName = "shadow"});
    auto target = device->createTexture({.width = kMapSize,
                                         .height = kMapSize,
                                         .format = rhi::Format::RGBA8,
                                         .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{target.get(), 0};
    auto framebuffer = device->createFramebuffer({.colors = {&attachment, 1}});
    auto commands = device->createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get()});
    commands->bindPipeline(*pipeline);
    commands->bindUniformBuffer(0, *uniforms, 0, sizeof(glm::mat4));
    commands->bindTexture(1, *map, *sampler);
    commands->draw(3);
    commands->endPass();
    device->submit(*commands);

    const rhi::Image mask = rhi::readTexture(*device, *target);
    const std::string picture = savePicture(mask, configuration() + "/shadow-mask");
    int wrong = 0;
    for (std::uint32_t y = 0; y < kMapSize; ++y)
        for (std::uint32_t x = 0; x < kMapSize; ++x) {
            if (x == kMapSize / 2 - 1 || x == kMapSize / 2)
                continue; // the occluder's edge
            const std::uint8_t expected = x < kMapSize / 2 ? 0 : 255;
            wrong += pixel(mask, x, y)[0] != expected;
        }
    EXPECT_EQ(wrong, 0) << "pixels with the wrong lit/shadowed value, see " << picture;
}

TEST_F(ShadowPrimitivesTest, DepthBiasMovesDepthAwayFromTheLight)
{
    // A slanted caster: view depth 2 at the left edge, 6 at the right.
    const std::vector<glm::vec3> slanted = quad({-1, -1}, {1, 1}, -2.0f, -6.0f);
    auto unbiasedMap = shadowMap();
    auto unbiased = casterPipeline();
    renderCasters(*unbiasedMap, *unbiased, slanted);
    const rhi::DepthImage reference = rhi::readDepth(*device, *unbiasedMap);

    struct Variant {
        const char* name;
        rhi::DepthBias bias;
        bool throughSetDepthBias;
    };
    for (const Variant& v :
         {Variant{"slope (pipeline)", {.slope = 4.0f}, false}, Variant{"slope (setDepthBias)", {.slope = 4.0f}, true},
          Variant{"constant (pipeline)", {.constant = 64.0f}, false}}) {
        auto map = shadowMap();
        auto pipeline = casterPipeline(v.throughSetDepthBias ? rhi::DepthBias{} : v.bias);
        renderCasters(*map, *pipeline, slanted, v.throughSetDepthBias ? std::optional(v.bias) : std::nullopt);
        const rhi::DepthImage biased = rhi::readDepth(*device, *map);
        int notFarther = 0;
        for (std::size_t i = 0; i < biased.depth.size(); ++i)
            notFarther += device->conventions().viewDepth(lightProjection, biased.depth[i]) <=
                          device->conventions().viewDepth(lightProjection, reference.depth[i]);
        EXPECT_EQ(notFarther, 0) << v.name << ": texels whose biased depth is not farther from the light";
    }
}

TEST_F(ShadowPrimitivesTest, DepthClampPancakesCastersInFrontOfTheNearPlane)
{
    ASSERT_TRUE(device->capabilities().depthClamp);
    auto map = shadowMap();
    auto pipeline = device->createPipeline({
        .vertex = casterVertex.get(),
        .fragment = casterFragment.get(),
        .vertexLayout = {.buffers = {{.stride = sizeof(glm::vec3)}},
                         .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3}}},
        .depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer, .clamp = true},
        .depthFormat = rhi::Format::D32F,
    });
    renderCasters(*map, *pipeline, quad({-1, -1}, {1, 1}, -0.1f, -0.1f)); // in front of the near plane 0.5
    EXPECT_EQ(rhi::readDepth(*device, *map).at(10, 10), device->conventions().nearDepth());
}

TEST_F(ShadowPrimitivesTest, LinearComparisonFilteringFollowsTheCapability)
{
    auto map = shadowMap();
    auto linear = device->createSampler({.magFilter = rhi::Filter::Linear,
                                         .minFilter = rhi::Filter::Linear,
                                         .compare = true,
                                         .debugName = "linear shadow"});
    auto commands = device->createCommandList();
    if (device->capabilities().supportsLinearFilter(rhi::Format::D32F)) {
        EXPECT_NO_THROW(commands->bindTexture(0, *map, *linear));
        return;
    }
    try {
        commands->bindTexture(0, *map, *linear);
        FAIL() << "linear depth filtering accepted on " << device->capabilities().device;
    } catch (const rhi::UnsupportedError& e) {
        EXPECT_NE(std::string(e.what()).find("D32F"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace penumbra::testing
