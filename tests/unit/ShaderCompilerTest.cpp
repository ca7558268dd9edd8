#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <gtest/gtest.h>
#include <tuple>

namespace penumbra::rhi {
namespace {

const std::string header = Conventions(DepthRange::ZeroToOne, true).glslHeader();

TEST(ShaderCompilerTest, ReflectsUniformBlocksAndSamplers)
{
    const CompiledShader shader = compileShader({ShaderStage::Fragment, R"(#version 450
layout(std140, binding = 0) uniform Light { mat4 viewProjection; vec4 color; } light;
layout(binding = 3) uniform sampler2DShadow shadowMap;
layout(location = 0) out vec4 outColor;
void main() { outColor = light.color * texture(shadowMap, vec3(0.5, 0.5, PENUMBRA_FAR_DEPTH)); }
)",
                                                 "light.frag"},
                                                header);
    EXPECT_FALSE(shader.spirv.empty());
    ASSERT_EQ(shader.bindings.size(), 2u);
    EXPECT_EQ(shader.bindings[0].binding, 0u);
    EXPECT_EQ(shader.bindings[0].kind, BindingKind::UniformBuffer);
    EXPECT_EQ(shader.bindings[0].size, 80u);
    EXPECT_EQ(shader.bindings[1].binding, 3u);
    EXPECT_EQ(shader.bindings[1].kind, BindingKind::SampledTexture);
}

// The std140 layout the uniform-layout comparison checks C++ structs against (GLSL 4.60 section 7.6.2.2):
// a vec3 takes 12 bytes on a 16-byte boundary, a float may follow in its last 4, and array elements are
// rounded up to 16 bytes.
TEST(ShaderCompilerTest, ReflectsStd140MemberOffsetsAndSizes)
{
    const CompiledShader shader = compileShader({ShaderStage::Fragment, R"(#version 450
layout(std140, binding = 0) uniform Layout { vec3 direction; float range; float weights[3]; ivec4 config; } l;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(l.direction, l.range + l.weights[1] + float(l.config.x)); }
)",
                                                 "layout.frag"},
                                                header);
    ASSERT_EQ(shader.bindings.size(), 1u);
    const ShaderBinding& block = shader.bindings[0];
    EXPECT_EQ(block.name, "Layout");
    EXPECT_EQ(block.size, 80u);
    ASSERT_EQ(block.members.size(), 4u);
    const std::vector<std::tuple<std::string, std::uint32_t, std::uint32_t>> expected{{"direction", 0, 12},
                                                                                      {"range", 12, 4},
                                                                                      {"weights", 16, 48},
                                                                                      {"config", 64, 16}};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(block.members[i].name, std::get<0>(expected[i]));
        EXPECT_EQ(block.members[i].offset, std::get<1>(expected[i])) << block.members[i].name;
        EXPECT_EQ(block.members[i].size, std::get<2>(expected[i])) << block.members[i].name;
    }
}

TEST(ShaderCompilerTest, ConventionsHeaderCompilesInEveryConvention)
{
    const std::string source = R"(#version 450
layout(location = 0) in vec4 position;
void main() {
    vec4 clip = penumbraClampToNearPlane(position);
    gl_Position = penumbraIsNearer(clip.z, PENUMBRA_NEAR_DEPTH) ? PENUMBRA_CLIP_TO_TEXTURE * clip : clip;
}
)";
    for (DepthRange range : {DepthRange::ZeroToOne, DepthRange::MinusOneToOne})
        for (bool reversed : {false, true})
            EXPECT_NO_THROW(
                compileShader({ShaderStage::Vertex, source, "header.vert"}, Conventions(range, reversed).glslHeader()));
}

TEST(ShaderCompilerTest, ErrorsCiteFileAndLine)
{
    try {
        compileShader({ShaderStage::Fragment, "#version 450\nvoid main()\n{\n    undeclaredThing = 1.0;\n}\n",
                       "broken.frag"},
                      header);
        FAIL() << "a broken shader compiled";
    } catch (const ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.frag:4"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("undeclaredThing"), std::string::npos) << e.what();
    }
}

TEST(ShaderCompilerTest, IncludesResolveAndTheirErrorsCiteTheIncludedFile)
{
    ShaderSource source{ShaderStage::Fragment,
                        "#version 450\n#include \"colour.glsl\"\nlayout(location = 0) out vec4 outColor;\n"
                        "void main() { outColor = colour(); }\n",
                        "includer.frag",
                        {{"colour.glsl", "vec4 colour() { return vec4(1.0); }\n"}}};
    EXPECT_NO_THROW(compileShader(source, header));

    source.includes[0].source = "vec4 colour()\n{\n    return missingThing;\n}\n";
    try {
        compileShader(source, header);
        FAIL() << "a broken include compiled";
    } catch (const ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("colour.glsl:3"), std::string::npos) << e.what();
    }

    source.includes.clear();
    EXPECT_THROW(compileShader(source, header), ShaderCompileError);
}

// Found by the shader fuzz target: an include that includes itself recursed in glslang until memory ran out.
TEST(ShaderCompilerTest, AnIncludeThatIncludesItselfIsRefused)
{
    const ShaderSource source{ShaderStage::Fragment,
                              "#version 450\n#include \"loop.glsl\"\nlayout(location = 0) out vec4 outColor;\n"
                              "void main() { outColor = vec4(1.0); }\n",
                              "looping.frag",
                              {{"loop.glsl", "#include \"loop.glsl\"\n"}}};
    try {
        compileShader(source, header);
        FAIL() << "a self-including shader compiled";
    } catch (const ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("\"loop.glsl\" nested deeper than 32 includes"), std::string::npos)
            << e.what();
    }
}

TEST(ShaderCompilerTest, PushConstantsAreRefusedWithTheReason)
{
    try {
        compileShader({ShaderStage::Vertex, R"(#version 450
layout(push_constant) uniform Push { mat4 m; } push;
void main() { gl_Position = push.m[0]; }
)",
                       "push.vert"},
                      header);
        FAIL() << "push constants accepted";
    } catch (const ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("push.vert"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("push constants"), std::string::npos) << e.what();
    }
}

TEST(ShaderCompilerTest, BindingsNeedExplicitNumbers)
{
    EXPECT_THROW(compileShader({ShaderStage::Fragment, R"(#version 450
layout(std140) uniform Block { vec4 v; } block;
layout(location = 0) out vec4 o;
void main() { o = block.v; }
)",
                                "nobinding.frag"},
                               header),
                 ShaderCompileError);
}

} // namespace
} // namespace penumbra::rhi
