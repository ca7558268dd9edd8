#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Pipeline.hpp"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace penumbra::rhi {

// Faces of a cube texture (TextureDesc::cube) in layer order, as both APIs number them.
enum class CubeFace : std::uint8_t { PositiveX, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };

inline constexpr std::array<CubeFace, 6> allCubeFaces{CubeFace::PositiveX, CubeFace::NegativeX, CubeFace::PositiveY,
                                                      CubeFace::NegativeY, CubeFace::PositiveZ, CubeFace::NegativeZ};

// The texture layer of one face of cube `cube` in a cube-map array: what an Attachment, a copy
// or a readback names, and what GL calls the layer-face.
constexpr std::uint32_t cubeLayer(std::uint32_t cube, CubeFace face) { return 6 * cube + std::uint32_t(face); }

// World-to-view matrix for rendering `face` of a cube centred at `position` (a point light), with
// cubeFaceProjection, such that sampling the cube with direction d = point - position finds the
// rendered point exactly where it was drawn, on every backend.
//
// Derivation: hardware cube sampling (GL 4.5 section 8.13, table 8.19; Vulkan "Cube Map Face
// Selection", the same table) picks the face of d's major axis ma and addresses it with
// s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2, where s runs along the row and t = 0 is row 0;
// e.g. +X: sc = -dz, tc = -dy. The RHI puts NDC y = +1 on row 0 (Conventions.hpp), so a face view
// must give x_ndc = sc / |ma|, y_ndc = -tc / |ma| and view depth |ma|, i.e. view x = sc,
// view y = -tc, view z = -|ma|:
//   +X: ( -dz,  dy, -dx)   -X: ( dz,  dy,  dx)
//   +Y: (  dx, -dz, -dy)   -Y: ( dx,  dz,  dy)
//   +Z: (  dx,  dy, -dz)   -Z: (-dx,  dy,  dz)
// These views are MIRRORED (determinant -1): the cube's layout, seen from inside, is left-handed,
// and no right-handed camera produces it. Triangles front-facing in the world are therefore
// clockwise in NDC; draw with cubeFaceCullMode() (or viewCullMode()) to cull the intended side.
// The answer is the same on every backend, because the RHI hides the Y differences already.
glm::mat4 cubeFaceView(CubeFace face, const glm::vec3& position);

// The 90-degree, aspect-1 perspective that goes with cubeFaceView, in this convention.
glm::mat4 cubeFaceProjection(const Conventions& conventions, float zNear, float zFar);

// Positive view depth at which a face projection sees the point `direction` away from the cube's
// centre: the major-axis magnitude max(|dx|, |dy|, |dz|). With Conventions::windowDepth it gives the
// reference depth of a samplerCubeArrayShadow lookup.
float cubeFaceViewDepth(const glm::vec3& direction);

// Whether a world-to-view matrix mirrors space (negative determinant), which turns world
// counter-clockwise triangles clockwise in NDC. Projections from Conventions never mirror.
bool flipsWinding(const glm::mat4& view);

// The pipeline cull mode that culls `worldCull` (Back: faces turned away in the world) when drawing
// through `view`: Back and Front swap when the view mirrors.
CullMode viewCullMode(const glm::mat4& view, CullMode worldCull);

// viewCullMode for cubeFaceView, which always mirrors: CullMode::Back becomes CullMode::Front.
CullMode cubeFaceCullMode(CullMode worldCull);

} // namespace penumbra::rhi
