#include "penumbra/rhi/Conventions.hpp"

#include <cmath>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

// z_ndc = a * z_view + b (orthographic) or (a * z_view + b) / -z_view (perspective).
// Each case is written in closed form rather than derived by composing matrices, so that the
// reversed-Z coefficients keep their precision (1 - z computed in float cancels badly).
struct DepthRow {
    float a;
    float b;
};

DepthRow perspectiveRow(DepthRange range, bool reversed, float n, float f)
{
    if (range == DepthRange::ZeroToOne)
        return reversed ? DepthRow{n / (f - n), n * f / (f - n)} : DepthRow{f / (n - f), n * f / (n - f)};
    return reversed ? DepthRow{(f + n) / (f - n), 2.0f * f * n / (f - n)}
                    : DepthRow{-(f + n) / (f - n), -2.0f * f * n / (f - n)};
}

// Limit of perspectiveRow as f -> infinity.
DepthRow infiniteRow(DepthRange range, bool reversed, float n)
{
    if (range == DepthRange::ZeroToOne)
        return reversed ? DepthRow{0.0f, n} : DepthRow{-1.0f, -n};
    return reversed ? DepthRow{1.0f, 2.0f * n} : DepthRow{-1.0f, -2.0f * n};
}

DepthRow orthographicRow(DepthRange range, bool reversed, float n, float f)
{
    if (range == DepthRange::ZeroToOne)
        return reversed ? DepthRow{1.0f / (f - n), f / (f - n)} : DepthRow{-1.0f / (f - n), -n / (f - n)};
    return reversed ? DepthRow{2.0f / (f - n), (f + n) / (f - n)} : DepthRow{-2.0f / (f - n), -(f + n) / (f - n)};
}

glm::mat4 perspectiveMatrix(float fovY, float aspect, DepthRow row)
{
    const float g = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 m(0.0f);
    m[0][0] = g / aspect;
    m[1][1] = g;
    m[2][2] = row.a;
    m[2][3] = -1.0f;
    m[3][2] = row.b;
    return m;
}

std::string glslFloat(float v)
{
    return fmt::format("{:.9g}", v).find_first_of(".e") == std::string::npos ? fmt::format("{:.9g}.0", v)
                                                                             : fmt::format("{:.9g}", v);
}

} // namespace

float Conventions::nearClipValue() const
{
    if (reversedZ_)
        return 1.0f;
    return range_ == DepthRange::ZeroToOne ? 0.0f : -1.0f;
}

CompareOp Conventions::depthCompareOp(DepthTest test) const
{
    switch (test) {
    case DepthTest::Always:
        return CompareOp::Always;
    case DepthTest::Never:
        return CompareOp::Never;
    case DepthTest::Equal:
        return CompareOp::Equal;
    case DepthTest::Nearer:
        return reversedZ_ ? CompareOp::Greater : CompareOp::Less;
    case DepthTest::NearerOrEqual:
        return reversedZ_ ? CompareOp::GreaterOrEqual : CompareOp::LessOrEqual;
    case DepthTest::Farther:
        return reversedZ_ ? CompareOp::Less : CompareOp::Greater;
    case DepthTest::FartherOrEqual:
        return reversedZ_ ? CompareOp::LessOrEqual : CompareOp::GreaterOrEqual;
    }
    return CompareOp::Always;
}

glm::mat4 Conventions::clipToTexture() const
{
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f;
    m[3][0] = 0.5f;
    // v = 0 is the top row and NDC +y is up, hence the negative scale.
    m[1][1] = -0.5f;
    m[3][1] = 0.5f;
    if (range_ == DepthRange::MinusOneToOne) {
        m[2][2] = 0.5f;
        m[3][2] = 0.5f;
    }
    return m;
}

glm::mat4 Conventions::perspective(float fovY, float aspect, float zNear, float zFar) const
{
    return perspectiveMatrix(fovY, aspect, perspectiveRow(range_, reversedZ_, zNear, zFar));
}

glm::mat4 Conventions::perspectiveInfinite(float fovY, float aspect, float zNear) const
{
    return perspectiveMatrix(fovY, aspect, infiniteRow(range_, reversedZ_, zNear));
}

glm::mat4 Conventions::orthographic(float left, float right, float bottom, float top, float zNear, float zFar) const
{
    const DepthRow row = orthographicRow(range_, reversedZ_, zNear, zFar);
    glm::mat4 m(1.0f);
    m[0][0] = 2.0f / (right - left);
    m[1][1] = 2.0f / (top - bottom);
    m[3][0] = -(right + left) / (right - left);
    m[3][1] = -(top + bottom) / (top - bottom);
    m[2][2] = row.a;
    m[3][2] = row.b;
    return m;
}

float Conventions::viewDepth(const glm::mat4& projection, float windowDepth) const
{
    const float zNdc = range_ == DepthRange::ZeroToOne ? windowDepth : 2.0f * windowDepth - 1.0f;
    const float a = projection[2][2];
    const float b = projection[3][2];
    if (projection[2][3] != 0.0f)
        return b / (zNdc + a); // perspective: z_ndc = (a z + b) / -z
    return (b - zNdc) / a; // orthographic: z_ndc = a z + b
}

float Conventions::windowDepth(const glm::mat4& projection, float viewDepth) const
{
    const float a = projection[2][2];
    const float b = projection[3][2];
    const float zNdc = projection[2][3] != 0.0f ? b / viewDepth - a // perspective: (a z + b) / -z with z = -viewDepth
                                                : b - a * viewDepth;
    return range_ == DepthRange::ZeroToOne ? zNdc : 0.5f * zNdc + 0.5f;
}

std::string Conventions::glslHeader() const
{
    const glm::mat4 t = clipToTexture();
    std::string matrix;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            matrix += (c || r ? ", " : "") + glslFloat(t[c][r]);
    const bool nearerIsGreater = reversedZ_;
    return fmt::format(
        "// Generated by penumbra::rhi::Conventions; the same facts the C++ side uses.\n"
        "#define PENUMBRA_REVERSED_Z {}\n"
        "#define PENUMBRA_DEPTH_ZERO_TO_ONE {}\n"
        "const float PENUMBRA_NEAR_CLIP_VALUE = {};\n"
        "const float PENUMBRA_NEAR_DEPTH = {};\n"
        "const float PENUMBRA_FAR_DEPTH = {};\n"
        "const mat4 PENUMBRA_CLIP_TO_TEXTURE = mat4({});\n"
        "bool penumbraIsNearer(float depth, float than) {{ return depth {} than; }}\n"
        "// Pancaking: moves clip-space points in front of the near plane onto it.\n"
        "vec4 penumbraClampToNearPlane(vec4 clip) {{ clip.z = {}(clip.z, clip.w * PENUMBRA_NEAR_CLIP_VALUE); return clip; }}\n"
        "// Screen space back to NDC: a fragment's gl_FragCoord.xy in a width x height target (row 0 at the top,\n"
        "// NDC +y up) and a depth read from a depth texture (the depth range's inverse; reversed-Z is the\n"
        "// projection's, which the inverse view-projection undoes).\n"
        "vec2 penumbraFragCoordToNdc(vec2 fragCoord, vec2 size) {{ return vec2(2.0, -2.0) * fragCoord / size + vec2(-1.0, 1.0); }}\n"
        "float penumbraWindowDepthToNdc(float depth) {{ return {}; }}\n",
        reversedZ_ ? 1 : 0, range_ == DepthRange::ZeroToOne ? 1 : 0, glslFloat(nearClipValue()), glslFloat(nearDepth()),
        glslFloat(farDepth()), matrix, nearerIsGreater ? ">" : "<", reversedZ_ ? "min" : "max",
        range_ == DepthRange::ZeroToOne ? "depth" : "2.0 * depth - 1.0");
}

} // namespace penumbra::rhi
