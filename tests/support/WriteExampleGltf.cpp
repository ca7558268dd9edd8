// Writes the command-line tests' glTF scene (testing::exampleScene): write-example-gltf <file.gltf|file.glb>.
#include "GltfBuilder.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <file.gltf|file.glb>\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path path = argv[1];
        std::filesystem::create_directories(path.parent_path().empty() ? "." : path.parent_path());
        const penumbra::testing::GltfBuilder scene = penumbra::testing::exampleScene();
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
