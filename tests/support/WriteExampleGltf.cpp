// Writes the command-line tests' glTF scenes: write-example-gltf [KIND] <file.gltf|file.glb>, KIND one of
//   (none)          testing::exampleScene
//   materials       testing::materialsScene
//   bend            testing::twoBoneBendScene (a skin and an animation)
//   character       testing::walkingCharacterScene (a figure of boxes skinned to 11 joints, walking)
//   spheres         testing::metallicSpheresScene (no lights, no camera: the loader's defaults)
//   missing-image   testing::missingImageScene (its image file is not written)
//   truncated       testing::exampleScene cut half-way into its inline buffer (.gltf only)
//   large-textures  testing::largeTexturesScene(6, 2048): 12 PNGs of 2048 x 2048 texels, to time loading
#include "GltfAnimationScenes.hpp"
#include "GltfBuilder.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <string_view>

namespace {

using penumbra::testing::GltfBuilder;

GltfBuilder sceneOf(std::string_view kind)
{
    if (kind == "materials")
        return penumbra::testing::materialsScene();
    if (kind == "bend")
        return penumbra::testing::twoBoneBendScene();
    if (kind == "character")
        return penumbra::testing::walkingCharacterScene();
    if (kind == "spheres")
        return penumbra::testing::metallicSpheresScene();
    if (kind == "missing-image")
        return penumbra::testing::missingImageScene();
    if (kind == "large-textures")
        return penumbra::testing::largeTexturesScene(6, 2048);
    return penumbra::testing::exampleScene();
}

} // namespace

int main(int argc, char** argv)
{
    const std::string_view kind = argc == 3 ? argv[1] : "";
    const bool known = kind.empty() || kind == "materials" || kind == "bend" || kind == "character" ||
                       kind == "spheres" || kind == "missing-image" || kind == "truncated" || kind == "large-textures";
    if ((argc != 2 && argc != 3) || !known) {
        std::fprintf(
            stderr,
            "usage: %s [materials|bend|character|spheres|missing-image|truncated|large-textures] <file.gltf|file.glb>\n",
            argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path path = argv[argc - 1];
        std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
        const GltfBuilder scene = sceneOf(kind);
        if (kind == "truncated")
            std::ofstream(path, std::ios::binary) << penumbra::testing::truncatedGltf(scene);
        else if (path.extension() == ".glb")
            scene.writeGlb(path);
        else
            scene.writeGltf(path, true);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "write-example-gltf: %s\n", e.what());
        return 1;
    }
    return 0;
}
