// A glTF scene (or the built-in shadow test scene) with cascaded, spot and point shadows through
// penumbra::render, into scene.png:   shadowed_scene [--backend B] [file.gltf | file.glb]
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>
#include <penumbra/gltf/GltfLoader.hpp>
#include <penumbra/render/SceneRenderer.hpp>
#include <penumbra/scenes/TestScenes.hpp>

#include <iostream>

using namespace penumbra;

namespace {

scene::Scene loadScene(const std::string& file)
{
    if (file.empty())
        return scenes::makeShadowTestScene();
    gltf::GltfScene loaded = gltf::loadGltf(file);
    for (const std::string& note : loaded.notes)
        std::cout << file << ": " << note << '\n';
    return std::move(loaded.scene);
}

} // namespace

int main(int argc, char** argv)
try {
    std::string file;
    auto device = createDevice(examples::backendArgument(argc, argv, &file));
    const scene::Scene world = loadScene(file);

    render::SceneRenderer renderer(*device, world);
    const render::FrameDesc frame{.width = 960, .height = 540};
    const render::FrameStats stats = renderer.render(world.camera, frame);
    for (const std::string& note : stats.notes)
        std::cout << "note: " << note << '\n';

    examples::writePng("scene.png", rhi::readTexture(*device, renderer.litImage()));
    std::cout << "scene.png: " << world.objects.size() << " objects, " << stats.casterDraws
              << " directional caster draws, on " << configurationName(device->desc()) << '\n';
} catch (const std::exception& e) {
    std::cerr << "shadowed_scene: " << e.what() << '\n';
    return 1;
}
