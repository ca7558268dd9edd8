// The built-in shadow test scene with the distance fog of FogPass.hpp, a pass of the application's in the frame
// graph, into fog_pass.png:   fog_pass [--backend B]
#include "ExampleSupport.hpp"
#include "FogPass.hpp"

#include <penumbra/backends/CreateDevice.hpp>
#include <penumbra/scenes/TestScenes.hpp>

#include <iostream>

int main(int argc, char** argv)
try {
    using namespace penumbra;
    auto device = createDevice(examples::backendArgument(argc, argv));
    constexpr std::uint32_t width = 960, height = 540;
    examples::FoggedScene fogged(*device, scenes::makeShadowTestScene(), width, height);
    const render::FrameStats stats =
        fogged.renderer->render(fogged.scene.camera, render::FrameDesc{.width = width, .height = height});
    for (const render::PassTiming& pass : stats.passes)
        std::cout << pass.name << (pass.gpuMs ? " " + std::to_string(*pass.gpuMs) + " ms" : "") << '\n';
    examples::writePng("fog_pass.png", rhi::readTexture(*device, *fogged.fogged));
} catch (const std::exception& e) {
    std::cerr << "fog_pass: " << e.what() << '\n';
    return 1;
}
