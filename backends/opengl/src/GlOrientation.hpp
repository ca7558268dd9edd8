#pragma once

#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Conventions.hpp"

#include <array>

namespace penumbra::opengl {

class GlContext;

// The one place that decides how GL meets the canonical convention (NDC +y up lands on memory
// row 0 = the top, counter-clockwise front faces, viewport/scissor y counted from the top).
// - Clip control: glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE), Direct3D's clip volume. The spec
//   negates y_d (so clip +y reaches window row 0) and the area sign, so GL_CCW stays front-facing.
// - No clip control: GL's default LOWER_LEFT / [-1, 1]; the vertex stage negates y instead
//   (SPIRV-Cross flip_vert_y), which inverts the winding, so GL_CW is the canonical CCW.
// - The first vertex provokes, as in Vulkan: flat varyings agree, and llvmpipe orders a clockwise
//   triangle's vertices by the provoking vertex when it sets up the depth plane, so GL's default
//   (last) rounds depth differently from lavapipe.
// Either way window coordinates are untouched: window row 0 is memory row 0 of the attachment,
// gl_FragCoord.y counts rows from the top, and uploads and readbacks need no flip.
class GlOrientation {
public:
    explicit GlOrientation(bool clipControl) : clipControl_(clipControl) {}

    rhi::Conventions conventions(bool reversedZ) const;

    // Sets the provoking vertex and the clip volume on the current context; throws UnsupportedError
    // when clip control is asked for and missing.
    void apply(const GlContext& context) const;

    // For SPIRV-Cross: negate gl_Position.y at the end of every vertex shader.
    bool flipVertexY() const { return !clipControl_; }
    GLenum frontFace() const { return clipControl_ ? GL_CCW : GL_CW; }

    // Window rectangles: y already counts rows from memory row 0 (the top) in both modes,
    // because neither mode moves the window origin away from the attachment's first row.
    std::array<float, 4> viewport(const rhi::Viewport& v) const { return {v.x, v.y, v.width, v.height}; }
    std::array<GLint, 4> scissor(const rhi::Rect& r) const { return {r.x, r.y, GLint(r.width), GLint(r.height)}; }

private:
    bool clipControl_;
};

} // namespace penumbra::opengl
