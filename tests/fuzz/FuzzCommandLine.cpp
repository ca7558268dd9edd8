// libFuzzer target: the command line's light, ambient, size and camera (look-at) specifications; the first
// byte chooses the parser, the rest is the option's text. What parses is added to a scene that must validate.
#include "CommandLineSpecs.hpp"
#include "LightOption.hpp"

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    switch (data[0] % 4) {
    case 0:
        if (const auto light = penumbra::apps::parseLightOption(text)) {
            // Built once: generating the scene's meshes for every input held the target at 69 executions a second.
            static const penumbra::scene::Scene base = penumbra::scenes::makeSingleLightScene();
            penumbra::scene::Scene scene = base;
            penumbra::apps::addLight(scene, *light);
            scene.validate();
        }
        break;
    case 1:
        penumbra::apps::ambientFields(text);
        break;
    case 2:
        if (const auto parsed = penumbra::apps::parseSize(text);
            parsed && (parsed->width < 1 || parsed->width > penumbra::apps::kMaxSize))
            __builtin_trap();
        break;
    default:
        penumbra::apps::parseLookAt(text);
        break;
    }
    return 0;
}
