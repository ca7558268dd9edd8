#pragma once

#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Image.hpp"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::testing {

// A face of a cube seen from its centre: the world axis it looks along and the two other axes,
// in cyclic order (x -> y, z; y -> z, x; z -> x, y), whatever the face's texel layout.
struct CubeFaceFrame {
    glm::vec3 axis;
    glm::vec3 b;
    glm::vec3 c;
};
CubeFaceFrame cubeFaceFrame(rhi::CubeFace face);
// The face whose frustum holds direction d (its major axis); ties are not expected.
rhi::CubeFace majorFace(const glm::vec3& d);

// The direction hardware cube sampling reads texel (x, y) of `face` from: GL 4.5 table 8.19 and
// Vulkan "Cube Map Face Selection" inverted, t = 0 on row 0. Independent of rhi::cubeFaceView.
glm::vec3 cubeTexelDirection(rhi::CubeFace face, std::uint32_t x, std::uint32_t y, std::uint32_t size);

struct CubeVertex {
    glm::vec3 position;
    glm::vec4 color;
};

// Appends a quad in the plane at `distance` along the face's axis from `centre`, spanning face
// coordinates (b, c) in bRange x cRange measured at unit distance (so its direction extent does
// not depend on `distance`), wound counter-clockwise as seen from the centre when facingCentre.
void addCubeQuad(std::vector<CubeVertex>& out, const glm::vec3& centre, rhi::CubeFace face, float distance,
                 glm::vec2 bRange, glm::vec2 cRange, const glm::vec4& color, bool facingCentre = true);

// Renders triangle lists into the six faces of cube `cube` of a cube texture, through
// rhi::cubeFaceView / cubeFaceProjection, culling back faces with rhi::cubeFaceCullMode.
// A colour texture is drawn without depth; a depth texture without colour, nearer wins.
class CubeFaceRenderer {
public:
    CubeFaceRenderer(rhi::Device& device, rhi::Format format, float zNear, float zFar);

    void render(const rhi::Texture& cubeTexture, std::uint32_t cube, const glm::vec3& centre,
                std::span<const CubeVertex> triangles);
    const glm::mat4& projection() const { return projection_; }

private:
    rhi::Device& device_;
    glm::mat4 projection_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
};

// Draws one pixel per probe into a probes x 1 RGBA8 target; `fragmentBody` computes outColor from
// `probe.direction[i]` (xyz direction, w cube index), `probe.reference[i].x` and the cube texture
// `cubeTexture` at binding 1, declared by `samplerType` (samplerCubeArray or samplerCubeArrayShadow).
rhi::Image sampleCubeProbes(rhi::Device& device, const rhi::Texture& cubeTexture, const rhi::Sampler& sampler,
                            const std::string& samplerType, const std::string& fragmentBody,
                            std::span<const glm::vec4> directions, std::span<const float> references = {});

// The six faces of a cube side by side (+X, -X, +Y, -Y, +Z, -Z), for looking at.
rhi::Image cubeStrip(rhi::Device& device, const rhi::Texture& cubeTexture, std::uint32_t cube);

} // namespace penumbra::testing
