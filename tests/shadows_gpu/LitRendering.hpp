#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Scene.hpp"

namespace penumbra::testing {

// The scene's lit image from its own camera, read back.
inline rhi::Image renderLit(rhi::Device& device, const scene::Scene& scene, const render::FrameDesc& frame)
{
    render::SceneRenderer renderer(device, scene);
    renderer.render(scene.camera, frame);
    return rhi::readTexture(device, renderer.litImage());
}

// The same scene with no material receiving shadows: what a shadow test compares against.
inline scene::Scene withoutShadows(scene::Scene scene)
{
    for (scene::Material& material : scene.materials)
        material.receiveShadows = false;
    return scene;
}

} // namespace penumbra::testing
