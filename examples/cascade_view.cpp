// A pass of one's own on top of the shadows module: SceneRenderer::planShadows gives the frame's
// shadow plan, render() fills the directional atlas from it, and a user shader reads both to colour
// the ground by cascade (red, green, blue, yellow) and darken it where the first light's atlas says
// it is shadowed. Writes cascades.png:   cascade_view [--backend B]
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>
#include <penumbra/render/SceneRenderer.hpp>
#include <penumbra/scenes/TestScenes.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <iostream>

using namespace penumbra;

namespace {

// std140, as the fragment shader declares it.
struct GroundUniforms {
    glm::mat4 clipToWorld;
    glm::mat4 worldToAtlas[4]; // the first light's cascades
    glm::vec4 cullingSpheres[4]; // per cascade: centre, radius squared
    glm::vec4 atlas; // size in texels, cascade count
};

const char* groundShader = R"(#version 450
layout(std140, binding = 0) uniform Ground {
    mat4 clipToWorld;
    mat4 worldToAtlas[4];
    vec4 cullingSpheres[4]; // per cascade: centre, radius squared
    vec4 atlas;
} ground;
layout(binding = 1) uniform sampler2D shadowAtlas; // raw depth, read with texelFetch
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 result;

void main()
{
    // The pixel's ray, intersected with the ground plane y = 0.
    vec4 near = ground.clipToWorld * vec4(ndc, PENUMBRA_NEAR_CLIP_VALUE, 1.0);
    vec4 far = ground.clipToWorld * vec4(ndc, PENUMBRA_FAR_DEPTH, 1.0);
    vec3 a = near.xyz / near.w, b = far.xyz / far.w;
    float t = a.y / (a.y - b.y);
    if (t <= 0.0 || a.y <= b.y) { result = vec4(0.1, 0.1, 0.1, 1.0); return; }
    // Lifted off the plane by a few centimetres, so the ground does not shadow itself.
    vec3 world = mix(a, b, t) + vec3(0.0, 0.05, 0.0);
    const vec3 colours[4] = vec3[](vec3(1, 0.2, 0.2), vec3(0.2, 1, 0.2), vec3(0.3, 0.4, 1), vec3(1, 1, 0.2));
    for (int c = 0; c < int(ground.atlas.y); ++c) {
        vec3 d = world - ground.cullingSpheres[c].xyz;
        if (dot(d, d) >= ground.cullingSpheres[c].w) continue;
        vec3 uvz = (ground.worldToAtlas[c] * vec4(world, 1.0)).xyz;
        float stored = texelFetch(shadowAtlas, ivec2(uvz.xy * ground.atlas.x), 0).r;
        result = vec4(colours[c] * (penumbraIsNearer(stored, uvz.z) ? 0.3 : 1.0), 1.0);
        return;
    }
    result = vec4(0.5, 0.5, 0.5, 1.0); // beyond the shadow distance
})";

const char* fullscreenShader = R"(#version 450
layout(location = 0) out vec2 ndc;
void main()
{
    ndc = vec2(gl_VertexIndex == 1 ? 3.0 : -1.0, gl_VertexIndex == 2 ? 3.0 : -1.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
})";

} // namespace

int main(int argc, char** argv)
try {
    auto device = createDevice(examples::backendArgument(argc, argv));
    const scene::Scene world = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, world);
    const render::FrameDesc frame{.width = 960, .height = 540};
    const render::ShadowPlans plans = renderer.planShadows(world.camera, frame);
    renderer.render(world.camera, frame, plans);

    const shadows::DirectionalShadowPlan& plan = plans.directional;
    GroundUniforms uniforms{};
    const glm::mat4 projection =
        device->conventions().perspective(world.camera.fovY, float(frame.width) / float(frame.height),
                                          world.camera.nearPlane, world.camera.farPlane);
    uniforms.clipToWorld = glm::inverse(projection * world.camera.view());
    for (std::uint32_t c = 0; c < plan.splits.count; ++c) {
        uniforms.worldToAtlas[c] = plan.lights.at(0).cascades.at(c).worldToAtlas;
        const shadows::CascadeData& cascade = plan.uniforms.cascades[c];
        uniforms.cullingSpheres[c] = glm::vec4(cascade.selectionCentre, cascade.selectionRadiusSquared);
    }
    uniforms.atlas = glm::vec4(float(renderer.atlas().size()), float(plan.splits.count), 0.0f, 0.0f);
    auto uniformBuffer = device->createBuffer({.size = sizeof(uniforms), .usage = rhi::BufferUsage::Uniform});
    uniformBuffer->writeObject(uniforms);

    auto color =
        device->createTexture({.width = frame.width, .height = frame.height, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{color.get(), 0};
    auto target = device->createFramebuffer({.colors = {&attachment, 1}});
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, fullscreenShader, "fullscreen.vert"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, groundShader, "ground.frag"});
    auto pipeline = device->createPipeline({.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{}}});
    auto sampler = device->createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});

    auto commands = device->createCommandList();
    commands->beginPass({.framebuffer = target.get()});
    commands->bindPipeline(*pipeline);
    commands->bindUniformBuffer(0, *uniformBuffer, 0, sizeof(uniforms));
    commands->bindTexture(1, renderer.atlas().texture(), *sampler);
    commands->draw(3);
    commands->endPass();
    device->submit(*commands);
    examples::writePng("cascades.png", rhi::readTexture(*device, *color));
    std::cout << "cascades.png: " << plan.splits.count << " cascades, atlas " << renderer.atlas().size() << '\n';
} catch (const std::exception& e) {
    std::cerr << "cascade_view: " << e.what() << '\n';
    return 1;
}
