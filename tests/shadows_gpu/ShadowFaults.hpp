#pragma once

// Faults for the negative controls: shadow plans as a planner with one bug would make them, drawn by the
// real renderer (SceneRenderer::render with plans), so a check can show it notices the bug.
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::testing {

// Either fit without its texel snap: every cascade's tile centred on what it is fitted around (the culling sphere,
// the slice's bounds), wherever that falls between texels, so that the shadow texels move with the camera.
inline shadows::DirectionalShadowPlan withoutTexelSnap(shadows::DirectionalShadowPlan plan,
                                                       const rhi::Conventions& conventions)
{
    for (shadows::ShadowedDirectionalLight& light : plan.lights)
        for (shadows::DirectionalCascadePlan& cascade : light.cascades) {
            shadows::DirectionalShadowCascade& fit = cascade.fit;
            fit.view =
                glm::translate(glm::mat4(1.0f), glm::vec3(fit.snappedCentre - fit.fittedCentre, 0.0f)) * fit.view;
            fit.viewProjection = fit.projection * fit.view;
            cascade.worldToAtlas = shadows::worldToAtlas(fit.viewProjection, cascade.tile, plan.atlas, conventions);
            plan.uniforms.worldToAtlas[cascade.tile] = cascade.worldToAtlas;
        }
    return plan;
}

// Point light faces rendered with field of view `fov` (radians): 90 degrees is a plan without the FOV bias,
// less leaves strips of directions that no face covers. Tiles keep their normal bias; cube maps are still
// sampled as 90-degree faces.
inline shadows::LocalShadowPlan withPointFaceFieldOfView(shadows::LocalShadowPlan plan, const scene::Scene& scene,
                                                         float fov, const rhi::Conventions& conventions,
                                                         const shadows::LocalShadowSettings& settings = {})
{
    for (std::size_t i = 0; i < scene.pointLights.size(); ++i) {
        const int first = plan.pointShadows.at(i);
        if (first < 0)
            continue;
        const scene::PointLight& light = scene.pointLights[i];
        const glm::mat4 projection =
            conventions.perspective(fov, 1.0f,
                                    shadows::localShadowNearPlane(light.range, light.shadowNearPlane, settings),
                                    light.range);
        for (const shadows::CubeFace face : rhi::allCubeFaces) {
            const auto f = static_cast<std::uint32_t>(face);
            if (plan.cubes.empty()) {
                shadows::LocalAtlasTile& tile = plan.tiles.at(static_cast<std::uint32_t>(first) + f);
                tile.view.projection = projection;
                tile.view.viewProjection = projection * shadows::pointFaceView(face, light.position);
                plan.tileData.at(tile.tile).worldToAtlas =
                    shadows::worldToAtlas(tile.view.viewProjection, glm::uvec2(tile.viewport.x, tile.viewport.y),
                                          static_cast<std::uint32_t>(tile.viewport.width), plan.atlasSize, conventions);
            } else {
                shadows::LocalShadowView& view = plan.cubes.at(static_cast<std::size_t>(first)).faces[f];
                view.projection = projection;
                view.viewProjection = projection * rhi::cubeFaceView(face, light.position);
            }
        }
    }
    return plan;
}

// The local atlas's old limit of 16 tiles come back: the lights past it keep no tile (lit without shadows, as
// before the packer and the storage block).
inline shadows::LocalShadowPlan withSixteenLocalTiles(shadows::LocalShadowPlan plan)
{
    constexpr std::size_t kOldLimit = 16;
    if (plan.tiles.size() > kOldLimit) {
        plan.tiles.resize(kOldLimit);
        plan.tileData.resize(kOldLimit);
    }
    for (std::vector<int>* firsts : {&plan.spotTiles, &plan.pointShadows})
        for (int& first : *firsts)
            if (plan.cubes.empty() && first >= 0 && std::size_t(first) >= kOldLimit)
                first = -1;
    return plan;
}

} // namespace penumbra::testing
