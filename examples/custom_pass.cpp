// The custom pass of CustomPass.hpp into custom_pass.png:   custom_pass [--backend B]
#include "CustomPass.hpp"
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>

#include <iostream>

int main(int argc, char** argv)
try {
    auto device = penumbra::createDevice(examples::backendArgument(argc, argv));
    examples::CustomPass pass(*device, 256, 256);
    pass.render();
    examples::writePng("custom_pass.png", pass.color());
} catch (const std::exception& e) {
    std::cerr << "custom_pass: " << e.what() << '\n';
    return 1;
}
