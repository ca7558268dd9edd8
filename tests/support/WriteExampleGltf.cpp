// Writes the command-line tests' glTF scene (testing::exampleScene), or with `materials` the material features'
// scene (testing::materialsScene), or with `bend` the animation tests' two-bone bend (testing::twoBoneBendScene):
// write-example-gltf [materials|bend] <file.gltf|file.glb>.
#include "GltfAnimationScenes.hpp"
#include "GltfBuilder.hpp"

#include <cstdio>
#include <exception>
#include <string_view>

int main(int argc, char** argv)
{
    const std::string_view kind = argc == 3 ? std::string_view(argv[1]) : "";
    if (argc != 2 && kind != "materials" && kind != "bend") {
        std::fprintf(stderr, "usage: %s [materials|bend] <file.gltf|file.glb>\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path path = argv[argc - 1];
        std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
        const penumbra::testing::GltfBuilder scene = kind == "materials" ? penumbra::testing::materialsScene()
                                                     : kind == "bend"    ? penumbra::testing::twoBoneBendScene()
                                                                         : penumbra::testing::exampleScene();
        if (path.extension() == ".glb")
            scene.writeGlb(path);
        else
            scene.writeGltf(path, true);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "write-example-gltf: %s\n", e.what());
        return 1;
    }
    return 0;
}
