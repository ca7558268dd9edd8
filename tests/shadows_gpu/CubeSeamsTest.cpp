// Point shadow face seams: where two faces of a point light meet, both must give the same shadow. The lit
// shader picks one face per receiver by the direction from the light (ties to x, then y, then z), so a
// pixel on one side of a face edge reads one face and its neighbour across the edge the other; a seam is a
// difference between the two larger than a correct filter gives over that distance. Probed on the room's
// surfaces at every point the twelve face edges' directions reach, lit and shadowed alike (every surface
// along each ray from the light, not only the first), so shadow boundaries that cross an edge are included.
// Each face is looked up in the read-back atlas or cube map exactly as shaders/local_shadows.glsl does.
#include "GpuTesting.hpp"
#include "ShadowFaults.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/TentFilter.hpp"
#include "penumbra/shadows/TentFilterReference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <ostream>
#include <set>
#include <vector>

namespace penumbra::shadows {
// Parameter values in failure messages.
void PrintTo(PointShadowMode mode, std::ostream* out)
{
    *out << (mode == PointShadowMode::Atlas ? "atlas" : "cubemap");
}
} // namespace penumbra::shadows

namespace penumbra::testing {
namespace {

using shadows::CubeFace;
using shadows::PointShadowMode;

constexpr shadows::ShadowFilter kFilter = shadows::ShadowFilter::PCF5x5;
constexpr int kSamplesPerEdge = 1500;

// Two receivers on one surface either side of the edge between two faces, a quarter texel from it: what
// neighbouring pixels across the edge look up, each through the face the lit shader picks for it.
struct EdgeProbe {
    glm::vec3 positions[2];
    glm::vec3 normal;
    CubeFace faces[2];
};

// Every receiving surface facing the light along a ray, nearest first, outside the room's closed objects: `rays`
// sees both sides, the ray enters an object through a face towards the light and leaves it through one facing away,
// and a surface it meets inside another object (the floor under a wall) is buried, no receiver.
std::vector<truth::Hit> receiversAlong(const scene::Scene& scene, const truth::RayCaster& rays, glm::vec3 light,
                                       glm::vec3 direction)
{
    std::vector<truth::Hit> hits;
    std::set<std::uint32_t> inside;
    float travelled = 0.0f;
    while (const auto hit = rays.closestHit(light + direction * travelled, direction)) {
        truth::Hit h = *hit;
        h.distance += travelled;
        travelled = h.distance + 1e-3f;
        if (glm::dot(h.normal, direction) >= 0.0f) {
            inside.erase(h.object);
            continue;
        }
        if (inside.empty() && scene.materialOf(scene.objects[h.object]).receiveShadows)
            hits.push_back(h);
        inside.insert(h.object);
    }
    return hits;
}

scene::Scene seenFromBothSides(scene::Scene scene)
{
    for (scene::Material& material : scene.materials)
        material.doubleSided = true;
    return scene;
}

// Along each of the twelve edges (two axes of equal magnitude), rays nudged a quarter texel (of a face
// `faceSize` texels wide) into either face; receivers paired where both rays meet the same surface.
std::vector<EdgeProbe> edgeProbes(const scene::Scene& scene, glm::vec3 light, std::uint32_t faceSize)
{
    const truth::RayCaster rays(seenFromBothSides(scene), truth::RayKind::Camera);
    // tan of the angle to the edge is 1 - 2 nudge: 2 nudge / (2 / faceSize) texels from it.
    const float nudge = 0.25f / float(faceSize);
    std::vector<EdgeProbe> probes;
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            for (const float sa : {1.0f, -1.0f})
                for (const float sb : {1.0f, -1.0f})
                    for (int i = 0; i < kSamplesPerEdge; ++i) {
                        const float along = -1.0f + 2.0f * (float(i) + 0.5f) / float(kSamplesPerEdge);
                        glm::vec3 direction[2];
                        std::vector<truth::Hit> hits[2];
                        for (int side = 0; side < 2; ++side) {
                            glm::vec3 d(0.0f);
                            d[a] = sa * (side == 0 ? 1.0f + nudge : 1.0f - nudge);
                            d[b] = sb * (side == 0 ? 1.0f - nudge : 1.0f + nudge);
                            d[3 - a - b] = along;
                            direction[side] = glm::normalize(d);
                            hits[side] = receiversAlong(scene, rays, light, direction[side]);
                        }
                        const CubeFace faces[2] = {static_cast<CubeFace>(2 * a + (sa > 0.0f ? 0 : 1)),
                                                   static_cast<CubeFace>(2 * b + (sb > 0.0f ? 0 : 1))};
                        for (std::size_t k = 0; k < std::min(hits[0].size(), hits[1].size()); ++k) {
                            const truth::Hit& h0 = hits[0][k];
                            const truth::Hit& h1 = hits[1][k];
                            if (h0.object != h1.object || glm::dot(h0.normal, h1.normal) < 0.999f)
                                break;
                            probes.push_back({{light + direction[0] * h0.distance, light + direction[1] * h1.distance},
                                              h0.normal,
                                              {faces[0], faces[1]}});
                        }
                    }
    return probes;
}

// The shadow (1 lit) at a receiver through one chosen face, as localAtlasShadow / cubeMapShadow compute it.
class PointShadowLookup {
public:
    PointShadowLookup(rhi::Device& device, const render::SceneRenderer& renderer, glm::vec3 light)
        : conventions_(device.conventions()), plan_(renderer.localPlan()), light_(light)
    {
        if (plan_.cubes.empty()) {
            const rhi::DepthImage atlas = rhi::readDepth(device, renderer.localAtlas().texture());
            for (std::uint32_t face = 0; face < shadows::cubeFaceCount; ++face) {
                const rhi::Viewport& place = plan_.tiles.at(firstTile() + face).viewport;
                const auto size = static_cast<std::uint32_t>(place.width);
                const glm::uvec2 offset(place.x, place.y);
                shadows::ShadowDepthGrid& grid = grids_[face];
                grid = {size, size, std::vector<float>(std::size_t(size) * size)};
                for (std::uint32_t y = 0; y < size; ++y)
                    for (std::uint32_t x = 0; x < size; ++x)
                        grid.depths[std::size_t(y) * size + x] = atlas.at(offset.x + x, offset.y + y);
            }
        } else {
            for (std::uint32_t face = 0; face < shadows::cubeFaceCount; ++face) {
                const rhi::DepthImage layer = rhi::readDepth(device, renderer.shadowCubes().texture(),
                                                             rhi::cubeLayer(0, static_cast<CubeFace>(face)));
                grids_[face] = {layer.width, layer.height, layer.depth};
            }
        }
    }

    float operator()(CubeFace face, glm::vec3 position, glm::vec3 normal) const
    {
        return plan_.cubes.empty() ? atlasShadow(face, position, normal) : cubeShadow(face, position, normal);
    }

private:
    std::uint32_t firstTile() const { return static_cast<std::uint32_t>(plan_.pointShadows.at(0)); }

    // Normal offset scaled by the distance to the face's plane, then the tile-clamped tent: clamp-to-edge
    // addressing of the tile's own texels is the shader's clamp to the tile bounds.
    float atlasShadow(CubeFace face, glm::vec3 position, glm::vec3 normal) const
    {
        const std::uint32_t tile = firstTile() + static_cast<std::uint32_t>(face);
        const float distanceToPlane = glm::dot(position - light_, shadows::cubeFaceAxis(face));
        const glm::vec3 biased =
            position + shadows::receiverNormalOffset(normal, glm::normalize(light_ - position),
                                                     distanceToPlane * plan_.tileData.at(tile).normalBias);
        const glm::vec4 p = plan_.tileData.at(tile).worldToAtlas * glm::vec4(biased, 1.0f);
        const rhi::Viewport& place = plan_.tiles.at(tile).viewport;
        const glm::vec2 texel = glm::vec2(p) / p.w * float(plan_.atlasSize) - glm::vec2(place.x, place.y);
        return shadows::filterShadowWithTaps(grids_[static_cast<std::size_t>(face)], kFilter, texel / place.width,
                                             p.z / p.w, conventions_.shadowCompareOp());
    }

    // A k x k box of nearest comparisons spread over the chosen face's texels; each tap's own major axis picks
    // the face it reads, as hardware cube sampling does (the faces' texel addressing: rhi::cubeFaceView).
    float cubeShadow(CubeFace face, glm::vec3 position, glm::vec3 normal) const
    {
        const shadows::LocalShadowCube& data = plan_.uniforms.cubes[0];
        const glm::vec3 axis = shadows::cubeFaceAxis(face);
        const glm::vec3 biased =
            position + shadows::receiverNormalOffset(normal, glm::normalize(light_ - position),
                                                     glm::dot(position - light_, axis) * data.normalBias);
        const glm::vec3 d = biased - light_;
        const float major = rhi::cubeFaceViewDepth(d);
        const float reference = (data.depthRow.x * -major + data.depthRow.y) / major;
        const int f = static_cast<int>(face);
        const glm::vec3 u =
            shadows::cubeFaceAxis(static_cast<CubeFace>((f + 2) % 6)) * (2.0f * major * data.invFaceSize);
        const glm::vec3 v =
            shadows::cubeFaceAxis(static_cast<CubeFace>((f + 4) % 6)) * (2.0f * major * data.invFaceSize);
        const int k = shadows::filterSize(kFilter);
        float lit = 0.0f;
        for (int y = 0; y < k; ++y)
            for (int x = 0; x < k; ++x) {
                const glm::vec3 tap = d + (float(x) - 0.5f * float(k - 1)) * u + (float(y) - 0.5f * float(k - 1)) * v;
                const CubeFace read = shadows::cubeFace(tap);
                const glm::vec3 view = glm::vec3(rhi::cubeFaceView(read, glm::vec3(0.0f)) * glm::vec4(tap, 1.0f));
                const shadows::ShadowDepthGrid& grid = grids_[static_cast<std::size_t>(read)];
                const float s = 0.5f * (view.x / -view.z + 1.0f) * float(grid.width);
                const float t = 0.5f * (1.0f - view.y / -view.z) * float(grid.height);
                lit += shadows::compareTexel(grid, int(std::floor(s)), int(std::floor(t)), reference,
                                             conventions_.shadowCompareOp());
            }
        return lit / float(k * k);
    }

    const rhi::Conventions& conventions_;
    const shadows::LocalShadowPlan& plan_;
    glm::vec3 light_;
    std::array<shadows::ShadowDepthGrid, shadows::cubeFaceCount> grids_;
};

// What a correct pair may differ by. The two faces' texels have the same size at the edge, and the two
// points lie half a texel apart: (1) each grid puts a shadow boundary at its own texel edges, at most one
// texel from the other's, and moving a boundary by one texel changes a filter by its largest one-texel
// column (the tent's largest texel weight along one axis, 0.36 for 5x5; 1 / k for the cube map's k x k box of
// nearest taps); (2) the half texel between the points moves the filter by half its largest slope per texel
// (the tent's peak, 2 / n per texel; the box again 1 / k per texel, taken whole as its taps are nearest).
float seamBound(PointShadowMode mode)
{
    const int n = shadows::filterSize(kFilter);
    if (mode == PointShadowMode::CubeMap)
        return 2.0f / float(n);
    float largest = 0.0f;
    for (float centre = 0.0f; centre < 1.0f; centre += 1.0f / 64.0f) {
        const shadows::TexelWeights w = shadows::tentTexelWeights(kFilter, centre);
        largest = std::max(largest, *std::max_element(w.weights.begin(), w.weights.begin() + w.count));
    }
    return largest + 0.5f * 2.0f / float(n);
}

struct CubeSeamFigures {
    std::size_t probes = 0;
    std::size_t partial = 0; // probes where a face sees a shadow boundary within its filter (value strictly in (0, 1))
    float largest = 0.0f; // largest difference between the two faces
    std::size_t beyondBound = 0;
};

class CubeSeamsTest : public GpuTest, public ::testing::WithParamInterface<PointShadowMode> {
protected:
    using PlanFault = std::function<render::ShadowPlans(render::ShadowPlans, const scene::Scene&)>;

    CubeSeamFigures measure(PointShadowMode mode, const PlanFault& fault = {})
    {
        scene::Scene scene = scenes::makePointLightRoomScene();
        scene.pointLights.pop_back();
        const glm::vec3 light = scene.pointLights[0].position;
        render::FrameDesc frame;
        frame.width = 64;
        frame.height = 36;
        frame.shadows.local.filter = kFilter;
        frame.shadows.local.pointMode = mode;
        render::SceneRenderer renderer(*device, scene);
        render::ShadowPlans plans = renderer.planShadows(scene.camera, frame);
        renderer.render(scene.camera, frame, fault ? fault(std::move(plans), scene) : std::move(plans));
        const PointShadowLookup lookup(*device, renderer, light);
        const float bound = seamBound(mode);
        CubeSeamFigures figures;
        const std::uint32_t faceSize =
            mode == PointShadowMode::Atlas
                ? static_cast<std::uint32_t>(renderer.localPlan()
                                                 .tiles.at(std::size_t(renderer.localPlan().pointShadows.at(0)))
                                                 .viewport.width)
                : frame.shadows.local.cubeMapSize;
        for (const EdgeProbe& probe : edgeProbes(scene, light, faceSize)) {
            const float a = lookup(probe.faces[0], probe.positions[0], probe.normal);
            const float b = lookup(probe.faces[1], probe.positions[1], probe.normal);
            ++figures.probes;
            figures.partial += (a > 0.0f && a < 1.0f) || (b > 0.0f && b < 1.0f);
            figures.largest = std::max(figures.largest, std::abs(a - b));
            figures.beyondBound += std::abs(a - b) > bound;
        }
        std::printf("[ seams    ] %s %s%s: %zu edge probes (%zu near shadow boundaries), largest difference between "
                    "the two faces %.4f (bound %.4f), %zu beyond\n",
                    configuration().c_str(), mode == PointShadowMode::Atlas ? "atlas" : "cube map",
                    fault ? " with a fault" : "", figures.probes, figures.partial, figures.largest, bound,
                    figures.beyondBound);
        return figures;
    }
};

TEST_P(CubeSeamsTest, FacesAgreeWhereTheyMeet)
{
    const CubeSeamFigures figures = measure(GetParam());
    RecordProperty("largestDifference", std::to_string(figures.largest));
    ASSERT_GT(figures.partial, 150u) << "shadow boundaries must cross the face edges";
    EXPECT_EQ(figures.beyondBound, 0u) << "largest difference " << figures.largest;
}

INSTANTIATE_TEST_SUITE_P(PointShadowModes, CubeSeamsTest,
                         ::testing::Values(PointShadowMode::Atlas, PointShadowMode::CubeMap),
                         [](const auto& param) { return param.param == PointShadowMode::Atlas ? "Atlas" : "CubeMap"; });

// Negative controls: faces of exactly 90 degrees (no FOV bias) let the filter and the normal bias run off
// the tile at the edges; narrower faces leave directions uncovered.
class CubeSeamFaultsTest : public CubeSeamsTest {
protected:
    PlanFault facesOf(float degrees)
    {
        return [this, degrees](render::ShadowPlans plans, const scene::Scene& scene) {
            plans.local =
                withPointFaceFieldOfView(std::move(plans.local), scene, glm::radians(degrees), device->conventions());
            return plans;
        };
    }
};

TEST_F(CubeSeamFaultsTest, MissingFovBiasCatchesFault)
{
    EXPECT_GT(measure(PointShadowMode::Atlas, facesOf(90.0f)).beyondBound, 0u);
}

// Cube maps narrowed this way shift every shadow towards the face centres, which the ground truth catches
// (ShadowMaskTest.NarrowCubeFacesCatchesFault); at the edges hardware face selection hides it.
TEST_F(CubeSeamFaultsTest, NarrowFacesCatchesFault)
{
    EXPECT_GT(measure(PointShadowMode::Atlas, facesOf(86.0f)).beyondBound, 0u);
}

} // namespace
} // namespace penumbra::testing
