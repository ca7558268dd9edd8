#pragma once

// An application's pass in Penumbra's frame graph, as a user would write it: distance fog over the lit picture. It
// runs after the built-in "lit" pass, reads the lit image and the lit depth by their names, and writes a texture of
// its own ("fogged image"). fog_pass.cpp writes its picture; fog_pass_parity_test.cpp proves it renders the same on
// every configuration.

#include <penumbra/render/FrameResources.hpp>
#include <penumbra/render/SceneRenderer.hpp>
#include <penumbra/rhi/UniformArena.hpp>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <memory>
#include <string>

namespace examples {

class FogPass final : public penumbra::render::FramePass {
public:
    static constexpr const char* kOutput = "fogged image";

    // `projection`: the camera's, from the device's conventions (the depth read back is that projection's).
    FogPass(penumbra::rhi::Device& device, const glm::mat4& projection, std::uint32_t width, std::uint32_t height)
    {
        using namespace penumbra::rhi;
        vertex_ = device.createShader({ShaderStage::Vertex, R"(#version 450
            const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
            void main() { gl_Position = vec4(corners[gl_VertexIndex], 0.0, 1.0); })"});
        // The depth back to view space through the inverse projection (the conventions' header gives the
        // window-to-NDC step for this device), then exponential fog over the view distance.
        fragment_ = device.createShader({ShaderStage::Fragment, R"(#version 450
            layout(std140, binding = 0) uniform Fog { mat4 inverseProjection; vec4 color; vec4 sizeAndDensity; } fog;
            layout(binding = 1) uniform sampler2D lit;
            layout(binding = 2) uniform sampler2D depth;
            layout(location = 0) out vec4 result;
            void main() {
                const ivec2 texel = ivec2(gl_FragCoord.xy);
                const float ndcDepth = penumbraWindowDepthToNdc(texelFetch(depth, texel, 0).r);
                const vec2 ndc = penumbraFragCoordToNdc(gl_FragCoord.xy, fog.sizeAndDensity.xy);
                const vec4 view = fog.inverseProjection * vec4(ndc, ndcDepth, 1.0);
                const float distance = length(view.xyz / view.w);
                const float clear = exp(-fog.sizeAndDensity.z * distance);
                result = vec4(mix(fog.color.rgb, texelFetch(lit, texel, 0).rgb, clear), 1.0);
            })"});
        pipeline_ = device.createPipeline({.vertex = vertex_.get(),
                                           .fragment = fragment_.get(),
                                           .colorTargets = {{.format = penumbra::render::kLitColorFormat}}});
        sampler_ = device.createSampler({.magFilter = Filter::Nearest, .minFilter = Filter::Nearest});
        const Uniforms uniforms{glm::inverse(projection), glm::vec4(0.62f, 0.66f, 0.72f, 1.0f),
                                glm::vec4(float(width), float(height), 0.04f, 0.0f)};
        uniforms_ = device.createBuffer({.size = sizeof(Uniforms), .usage = BufferUsage::Uniform});
        uniforms_->writeObject(uniforms);
    }

    std::string name() const override { return "fog"; }

    bool setup(penumbra::render::FramePassBuilder& builder) override
    {
        builder.read(penumbra::render::frame::kLitImage);
        builder.read(penumbra::render::frame::kLitDepth);
        builder.write(kOutput);
        return true;
    }

    void execute(const penumbra::render::FramePassContext& context) override
    {
        namespace frame = penumbra::render::frame;
        penumbra::rhi::CommandList& commands = context.commands();
        commands.beginPass({.framebuffer = &context.framebuffer({kOutput})});
        commands.bindPipeline(*pipeline_);
        commands.bindUniformBuffer(0, *uniforms_, 0, sizeof(Uniforms));
        commands.bindTexture(1, context.texture(frame::kLitImage), *sampler_);
        commands.bindTexture(2, context.texture(frame::kLitDepth), *sampler_);
        commands.draw(3);
        commands.endPass();
    }

private:
    struct Uniforms {
        glm::mat4 inverseProjection;
        glm::vec4 color;
        glm::vec4 sizeAndDensity; // target width and height, fog density per unit
    };

    std::unique_ptr<penumbra::rhi::Shader> vertex_, fragment_;
    std::unique_ptr<penumbra::rhi::Pipeline> pipeline_;
    std::unique_ptr<penumbra::rhi::Sampler> sampler_;
    std::unique_ptr<penumbra::rhi::Buffer> uniforms_;
};

// The built-in shadow test scene with fog, width x height: the renderer, the fog's output and the pass.
struct FoggedScene {
    penumbra::scene::Scene scene;
    std::unique_ptr<penumbra::rhi::Texture> fogged;
    std::unique_ptr<penumbra::render::SceneRenderer> renderer;

    FoggedScene(penumbra::rhi::Device& device, penumbra::scene::Scene world, std::uint32_t width, std::uint32_t height)
        : scene(std::move(world))
    {
        using namespace penumbra;
        fogged = device.createTexture({.width = width,
                                       .height = height,
                                       .format = render::kLitColorFormat,
                                       .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                       .debugName = FogPass::kOutput});
        renderer = std::make_unique<render::SceneRenderer>(device, scene);
        renderer->addTexture(FogPass::kOutput, *fogged);
        const scene::Camera& camera = scene.camera;
        const glm::mat4 projection = device.conventions().perspective(camera.fovY, float(width) / float(height),
                                                                      camera.nearPlane, camera.farPlane);
        renderer->addPass(std::make_shared<FogPass>(device, projection, width, height),
                          render::PassPlacement::after(std::string(render::frame::kLitPass)));
    }
};

} // namespace examples
