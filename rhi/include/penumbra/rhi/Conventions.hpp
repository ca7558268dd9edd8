#pragma once

#include <glm/mat4x4.hpp>
#include <string>

namespace penumbra::rhi {

// Coordinate system (the same on every backend; shaders and user code rely on it):
// - View space is right-handed, the camera looks down -z.
// - NDC: x right, y up; depth range per DepthRange below.
// - Window and texture rows: row 0 of every render target, readback and uploaded image is
//   the top of the picture; texture coordinate v = 0 addresses row 0. Viewport and scissor
//   y count rows from the top.
// - Front faces are counter-clockwise in NDC (y up).
// The backends meet this with a negative viewport height (Vulkan), glClipControl(UPPER_LEFT)
// (OpenGL), or a vertex-stage y flip with inverted winding (OpenGL without clip control).
// Cube textures follow from the same facts: CubeMap.hpp gives the (mirrored) view of each face.

enum class DepthRange { ZeroToOne, MinusOneToOne };

enum class CompareOp { Never, Less, LessOrEqual, Equal, Greater, GreaterOrEqual, NotEqual, Always };

// Depth tests stated by meaning; the conventions turn them into a CompareOp.
enum class DepthTest { Always, Never, Nearer, NearerOrEqual, Farther, FartherOrEqual, Equal };

// The only place where depth range and reversed-Z turn into numbers. Everything that
// touches depth (clear value, compare ops, bias sign, pancaking, projections, the
// clip-to-texture matrix of shadow lookups) asks this object.
class Conventions {
public:
    // The conventions of a depth range and a depth direction.
    Conventions(DepthRange range, bool reversedZ) : range_(range), reversedZ_(reversedZ) {}

    // Clip-space depth range: [0, 1] or [-1, 1].
    DepthRange depthRange() const { return range_; }
    // Whether the near plane maps to depth 1 and the far plane to 0.
    bool reversedZ() const { return reversedZ_; }

    // Window depth of the near and far planes; the depth clear value is farDepth().
    float nearDepth() const { return reversedZ_ ? 1.0f : 0.0f; }
    // Window depth of the far plane.
    float farDepth() const { return reversedZ_ ? 0.0f : 1.0f; }
    // The value depth attachments are cleared to: the far plane.
    float clearDepth() const { return farDepth(); }

    // NDC z of the near plane: 0, or -1 for [-1, 1], 1 reversed (Unity's UNITY_NEAR_CLIP_VALUE, which
    // Catlike Coding's "Directional Shadows" tutorial clamps to for shadow pancaking).
    float nearClipValue() const;

    // The compare op that makes `test` (nearer, nearer or equal, ...) true under these conventions.
    CompareOp depthCompareOp(DepthTest test) const;
    // A shadow lookup is lit where the receiver is nearer to the light than or as near as the stored depth.
    CompareOp shadowCompareOp() const { return depthCompareOp(DepthTest::NearerOrEqual); }
    // Depth bias is requested as "away from the viewer"; this is the sign the API needs.
    float depthBiasSign() const { return reversedZ_ ? -1.0f : 1.0f; }

    // Maps NDC to (u, v, window depth, 1): u = 0.5x + 0.5, v = 0.5 - 0.5y (row 0 at the top),
    // depth = z or 0.5z + 0.5. Shadow matrices are clipToTexture() * lightViewProjection.
    glm::mat4 clipToTexture() const;

    // Projections for this convention's depth range and direction (right-handed view space).
    glm::mat4 perspective(float fovY, float aspect, float zNear, float zFar) const;
    // Infinite far plane; with reversed-Z this is the precision-friendly z_ndc = near / view depth.
    glm::mat4 perspectiveInfinite(float fovY, float aspect, float zNear) const;
    // An orthographic projection to this depth range and direction (view space right-handed, looking down -z).
    glm::mat4 orthographic(float left, float right, float bottom, float top, float zNear, float zFar) const;

    // Positive view depth (distance along -z) of a window depth written through `projection`
    // (one of the helpers above, or any matrix of the same form).
    float viewDepth(const glm::mat4& projection, float windowDepth) const;
    // Its inverse: the window depth that `projection` gives a point at positive view depth `viewDepth`.
    float windowDepth(const glm::mat4& projection, float viewDepth) const;

    // GLSL text with the same facts; prepended to every shader the RHI compiles.
    std::string glslHeader() const;

private:
    // Turns a [0, 1]-depth, not-reversed projection into this convention's.
    glm::mat4 adapt(glm::mat4 zeroToOne) const;

    DepthRange range_;
    bool reversedZ_;
};

} // namespace penumbra::rhi
