#pragma once

// What every example shares: --backend B (any configuration name, default vulkan) and writing
// the picture as a PNG into the current folder.

#include <penumbra/imageio/ImageFiles.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace examples {

// The value of `--backend B`, else "vulkan"; the other argument (a file), if any, in `file`.
inline std::string backendArgument(int argc, char** argv, std::string* file = nullptr)
{
    std::string backend = "vulkan";
    for (int i = 1; i < argc; ++i) {
        if (std::string_view(argv[i]) == "--backend" && i + 1 < argc)
            backend = argv[++i];
        else if (file)
            *file = argv[i];
        else
            throw std::runtime_error(std::string("unexpected argument '") + argv[i] + "'");
    }
    return backend;
}

// An RGBA8 read-back (row 0 at the top, as every Penumbra readback) as a PNG.
inline void writePng(const std::string& path, const penumbra::rhi::Image& image)
{
    penumbra::imageio::writePngFile(path, image);
}

} // namespace examples
