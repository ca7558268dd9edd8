// A triangle through the RHI into triangle.png: the fewest lines the API allows.
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>

#include <iostream>

using namespace penumbra;

int main(int argc, char** argv)
try {
    auto device = createDevice(examples::backendArgument(argc, argv));
    auto color = device->createTexture({.width = 256, .height = 256, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{color.get(), 0};
    auto target = device->createFramebuffer({.colors = {&attachment, 1}});
    // Canonical NDC, y up, on every configuration; counter-clockwise, so front-facing.
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, R"(#version 450
        const vec2 corners[3] = vec2[](vec2(-0.8, -0.8), vec2(0.8, -0.8), vec2(0.0, 0.8));
        layout(location = 0) out vec3 colour;
        void main() { gl_Position = vec4(corners[gl_VertexIndex], 0.5, 1.0); colour = vec3(0.0); colour[gl_VertexIndex] = 1.0; })"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, R"(#version 450
        layout(location = 0) in vec3 colour;
        layout(location = 0) out vec4 result;
        void main() { result = vec4(colour, 1.0); })"});
    auto pipeline = device->createPipeline({.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{}}});
    auto commands = device->createCommandList();
    commands->beginPass({.framebuffer = target.get(), .clearColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)});
    commands->bindPipeline(*pipeline);
    commands->draw(3);
    commands->endPass();
    device->submit(*commands);
    examples::writePng("triangle.png", rhi::readTexture(*device, *color));
} catch (const std::exception& e) {
    std::cerr << "triangle: " << e.what() << '\n';
    return 1;
}
