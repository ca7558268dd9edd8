#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <functional>
#include <glm/vec2.hpp>
#include <string>

namespace penumbra::testing {

// The point-light room with its inside light only.
inline scene::Scene roomLitFromInside()
{
    scene::Scene room = scenes::makePointLightRoomScene();
    room.pointLights.pop_back();
    return room;
}

// A frame of the default settings with the given size, depth prepass and MSAA sample count.
inline render::FrameDesc litFrame(std::uint32_t width, std::uint32_t height, bool prepass, std::uint32_t msaa)
{
    render::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.depthPrepass = prepass;
    frame.msaa = msaa;
    return frame;
}

// The scene's lit image from its own camera, read back.
inline rhi::Image renderLit(rhi::Device& device, const scene::Scene& scene, const render::FrameDesc& frame)
{
    render::SceneRenderer renderer(device, scene);
    renderer.render(scene.camera, frame);
    return rhi::readTexture(device, renderer.litImage());
}

// The pixel a world point lands on in a width x height frame from `camera` (row 0 at the top).
inline glm::uvec2 pixelOf(const rhi::Device& device, const scene::Camera& camera, std::uint32_t width,
                          std::uint32_t height, glm::vec3 world)
{
    const glm::mat4 viewProjection =
        device.conventions().perspective(camera.fovY, float(width) / float(height), camera.nearPlane, camera.farPlane) *
        camera.view();
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {static_cast<std::uint32_t>((0.5f * ndc.x + 0.5f) * float(width)),
            static_cast<std::uint32_t>((0.5f - 0.5f * ndc.y) * float(height))};
}

// A change to the planned shadows before they are drawn: the negative controls' faults (ShadowFaults.hpp).
using PlanFault = std::function<render::ShadowPlans(render::ShadowPlans)>;

// renderLit with the plans changed by `fault`.
inline rhi::Image renderLit(rhi::Device& device, const scene::Scene& scene, const render::FrameDesc& frame,
                            const PlanFault& fault)
{
    render::SceneRenderer renderer(device, scene);
    renderer.render(scene.camera, frame, fault(renderer.planShadows(scene.camera, frame)));
    return rhi::readTexture(device, renderer.litImage());
}

// The same scene with no material receiving shadows: what a shadow test compares against.
inline scene::Scene withoutShadows(scene::Scene scene)
{
    for (scene::Material& material : scene.materials)
        material.receiveShadows = false;
    return scene;
}

// The same scene with object `name` casting no shadow and drawn as before (Object::castShadows off: a material
// whose caster mode is off would also lose its alpha-tested holes).
inline scene::Scene withoutCaster(scene::Scene scene, const std::string& name)
{
    scene.objects.at(scene.findObject(name).value()).castShadows = scene::ShadowCasting::Off;
    return scene;
}

} // namespace penumbra::testing
