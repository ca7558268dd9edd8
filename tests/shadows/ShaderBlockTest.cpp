// Blocks declared once (penumbra/shaders/ShaderBlock.hpp): the std140 and std430 rules, the generated GLSL and the
// layout that pipeline creation compares with reflection.

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace penumbra {
namespace {

struct Placed {
    float scale = 0.0f;
    std::int32_t count = 0;
    alignas(16) std::array<glm::vec4, 2> rows{};
    float last = 0.0f;
};
constexpr std::array kPlacedFields{PENUMBRA_SHADER_FIELD(Placed, scale), PENUMBRA_SHADER_FIELD(Placed, count),
                                   PENUMBRA_SHADER_FIELD(Placed, rows), PENUMBRA_SHADER_FIELD(Placed, last)};
constexpr shaders::ShaderStruct kPlaced{"Placed", 52, kPlacedFields};

// The same fields with the vec4 array where C++ puts it without alignas: right after the two scalars.
struct Misplaced {
    float scale = 0.0f;
    std::int32_t count = 0;
    std::array<glm::vec4, 2> rows{};
    float last = 0.0f;
};
constexpr std::array kMisplacedFields{PENUMBRA_SHADER_FIELD(Misplaced, scale), PENUMBRA_SHADER_FIELD(Misplaced, count),
                                      PENUMBRA_SHADER_FIELD(Misplaced, rows), PENUMBRA_SHADER_FIELD(Misplaced, last)};
constexpr shaders::ShaderStruct kMisplaced{"Misplaced", sizeof(Misplaced), kMisplacedFields};

// A float array: 16 bytes a float in std140 (rule 4), 4 in std430.
struct Floats {
    std::array<float, 4> values{};
};
constexpr std::array kFloatsFields{PENUMBRA_SHADER_FIELD(Floats, values)};
constexpr shaders::ShaderStruct kFloats{"Floats", sizeof(Floats), kFloatsFields};

// A texel record of two texels: a vec3 and a float in the first, a vec2 in the second.
struct TwoTexels {
    glm::vec3 position{0.0f};
    float range = 0.0f;
    glm::vec2 cone{0.0f};
    glm::vec2 padding{0.0f};
};
constexpr std::array kTwoTexelsFields{PENUMBRA_SHADER_FIELD(TwoTexels, position),
                                      PENUMBRA_SHADER_FIELD(TwoTexels, range), PENUMBRA_SHADER_FIELD(TwoTexels, cone)};
constexpr shaders::ShaderStruct kTwoTexels{"TwoTexels", sizeof(TwoTexels), kTwoTexelsFields};

// The vec3 straddles the two texels.
struct StraddlingTexels {
    float range = 0.0f;
    glm::vec2 cone{0.0f};
    glm::vec3 position{0.0f};
    float padding = 0.0f;
    glm::vec2 padding2{0.0f};
};
constexpr std::array kStraddlingFields{PENUMBRA_SHADER_FIELD(StraddlingTexels, range),
                                       PENUMBRA_SHADER_FIELD(StraddlingTexels, cone),
                                       PENUMBRA_SHADER_FIELD(StraddlingTexels, position)};
constexpr shaders::ShaderStruct kStraddling{"StraddlingTexels", sizeof(StraddlingTexels), kStraddlingFields};

// A storage block: a header, an array whose length a constant names, and a runtime array of vec4s after them.
constexpr shaders::ShaderConstant kBlockTestLanes{"TEST_LANES", 3};
struct LanesHeader {
    std::uint32_t count = 0;
    std::array<std::uint32_t, 3> lanes{};
};
constexpr std::array kLanesFields{PENUMBRA_SHADER_FIELD(LanesHeader, count),
                                  PENUMBRA_SHADER_FIELD(LanesHeader, lanes, kBlockTestLanes),
                                  shaders::runtimeArrayField<glm::vec4>("points", sizeof(LanesHeader))};
constexpr shaders::ShaderStruct kLanesBlock{"Lanes", sizeof(LanesHeader), kLanesFields};

// The runtime array right after a 4-byte header, where C++ would write it: std430 puts a vec4 at 16.
constexpr std::array kEarlyPointsFields{PENUMBRA_SHADER_FIELD(LanesHeader, count),
                                        shaders::runtimeArrayField<glm::vec4>("points", 4)};
constexpr shaders::ShaderStruct kEarlyPointsBlock{"EarlyPoints", 4, kEarlyPointsFields};

} // namespace

TEST(ShaderBlockTest, AStorageBlockNamesItsLengthsAndEndsInItsRuntimeArray)
{
    static_assert(shaders::matchesLayout(kLanesBlock, shaders::BlockLayout::Std430));
    EXPECT_EQ(shaders::storageBlockGlsl(kLanesBlock, 3, "lanes", shaders::BlockAccess::ReadOnly),
              "#ifndef PENUMBRA_TEST_LANES\n#define PENUMBRA_TEST_LANES 3\n#elif PENUMBRA_TEST_LANES != 3\n"
              "#error PENUMBRA_TEST_LANES is not 3, the length of Lanes.lanes\n#endif\n"
              "layout(std430, binding = 3) readonly buffer Lanes {\n    uint count;\n"
              "    uint lanes[PENUMBRA_TEST_LANES];\n    vec4 points[];\n} lanes;\n");
    // No instance name: the members are the shader's globals.
    const std::string globals = shaders::storageBlockGlsl(kLanesBlock, 0, "", shaders::BlockAccess::WriteOnly);
    EXPECT_NE(globals.find("layout(std430, binding = 0) writeonly buffer Lanes {\n"), std::string::npos) << globals;
    EXPECT_TRUE(globals.ends_with("    vec4 points[];\n};\n")) << globals;
    // As reflection gives it: the runtime array's size is its stride, and the block ends where the array begins.
    const rhi::UniformLayout layout = shaders::storageLayout(kLanesBlock);
    ASSERT_EQ(layout.members.size(), 3u);
    EXPECT_EQ(layout.members[2].name, "points");
    EXPECT_EQ(layout.members[2].offset, 16u);
    EXPECT_EQ(layout.members[2].size, 16u);
    EXPECT_EQ(layout.size, 16u);
}

TEST(ShaderBlockTest, ARuntimeArrayWhereStd430DoesNotPutItCatchesFault)
{
    EXPECT_FALSE(shaders::matchesLayout(kEarlyPointsBlock, shaders::BlockLayout::Std430));
    // A named length other than the C++ array's: a compile error where the field is constexpr, a throw here.
    static constexpr shaders::ShaderConstant kFour{"FOUR", 4};
    using ThreeFloats = std::array<float, 3>;
    EXPECT_THROW(shaders::shaderField<ThreeFloats>("values", 0, kFour), std::logic_error);
}

TEST(ShaderBlockTest, ATexelRecordGetsAnAccessorPerNamedField)
{
    static_assert(shaders::fitsTexels(kTwoTexels));
    EXPECT_EQ(shaders::texelRecordGlsl(kTwoTexels, "fetchLight", "light"),
              "// Generated from the texel record TwoTexels (2 texels).\n"
              "vec3 lightPosition(int record) { return fetchLight(record, 0).xyz; }\n"
              "float lightRange(int record) { return fetchLight(record, 0).w; }\n"
              "vec2 lightCone(int record) { return fetchLight(record, 1).xy; }\n");
}

TEST(ShaderBlockTest, ATexelRecordFieldAcrossTwoTexelsIsRefused)
{
    EXPECT_EQ(offsetof(StraddlingTexels, position), 12u);
    EXPECT_FALSE(shaders::fitsTexels(kStraddling));
    EXPECT_THROW(shaders::texelRecordGlsl(kStraddling, "fetchLight", "light"), std::invalid_argument);
}

TEST(ShaderBlockTest, AStructPlacedAsStd140PlacesItMatches)
{
    static_assert(shaders::matchesLayout(kPlaced, shaders::BlockLayout::Std140));
    EXPECT_TRUE(shaders::matchesLayout(kPlaced, shaders::BlockLayout::Std140));
}

TEST(ShaderBlockTest, AVec4ArrayAfterTwoScalarsWithoutAlignmentCatchesFault)
{
    EXPECT_EQ(offsetof(Misplaced, rows), 8u);
    EXPECT_FALSE(shaders::matchesLayout(kMisplaced, shaders::BlockLayout::Std140));
}

TEST(ShaderBlockTest, Std430PacksScalarArraysThatStd140PadsToVec4s)
{
    EXPECT_TRUE(shaders::matchesLayout(kFloats, shaders::BlockLayout::Std430));
    EXPECT_FALSE(shaders::matchesLayout(kFloats, shaders::BlockLayout::Std140));
}

TEST(ShaderBlockTest, TheGeneratedBlockDeclaresEveryFieldAndItsStructTypes)
{
    const std::string glsl = shaders::uniformBlockGlsl(shadows::kDirectionalShadowBlock, 2, "shadows");
    EXPECT_NE(glsl.find("struct DirectionalShadowLight {\n    float strength;\n    float normalBias;\n"
                        "    int firstTile;\n    int shadowFilter;\n"),
              std::string::npos)
        << glsl;
    EXPECT_NE(glsl.find("layout(std140, binding = 2) uniform DirectionalShadows {\n    mat4 worldToAtlas[16];\n"),
              std::string::npos)
        << glsl;
    EXPECT_NE(glsl.find("    DirectionalShadowLight lights[4];\n"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("    SoftControls soft;\n"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("} shadows;\n"), std::string::npos) << glsl;
}

TEST(ShaderBlockTest, TheLayoutListsTheFieldsOfStructFieldsAsReflectionDoes)
{
    const rhi::UniformLayout layout = shaders::uniformLayout(shadows::kDirectionalShadowBlock);
    const auto member = [&](const std::string& name) {
        const auto found = std::find_if(layout.members.begin(), layout.members.end(),
                                        [&](const rhi::UniformMember& m) { return m.name == name; });
        EXPECT_NE(found, layout.members.end()) << name;
        return found == layout.members.end() ? rhi::UniformMember{} : *found;
    };
    const std::uint32_t lights = offsetof(shadows::DirectionalShadowUniforms, lights);
    EXPECT_EQ(member("lights").size, sizeof(shadows::DirectionalShadowUniforms::lights));
    EXPECT_EQ(member("lights.firstTile").offset, lights + offsetof(shadows::DirectionalShadowLight, firstTile));
    // A struct that is not an array ends at its last member, as reflection sizes it.
    EXPECT_EQ(member("soft").size, offsetof(shadows::SoftShadowUniforms, diskRotation) + 4);
    EXPECT_EQ(member("soft.poissonRadius").offset, offsetof(shadows::DirectionalShadowUniforms, soft) +
                                                       offsetof(shadows::SoftShadowUniforms, poissonRadius));
    EXPECT_EQ(layout.size, offsetof(shadows::DirectionalShadowUniforms, tileBounds) +
                               sizeof(shadows::DirectionalShadowUniforms::tileBounds));
}

} // namespace penumbra
