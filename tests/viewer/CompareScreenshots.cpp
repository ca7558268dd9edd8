// compare-screenshots: checks the viewer's screenshots against `penumbra render`.
//   scene <render.png> <view.png> <min PSNR dB>: same size, PSNR at least the threshold.
//   panel <without-ui.png> <with-ui.png> <panel right edge x>: the pictures differ, and only left
//   of the edge (where the panel is drawn).
// Prints max difference, PSNR and differing pixels; exits 1 on failure, naming both files.
#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/parity/ImageDifference.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <string>

namespace {

using penumbra::imageio::readPng;

int compareScene(const std::string& reference, const std::string& view, double minPsnr)
{
    const penumbra::parity::ImageDifference d = penumbra::parity::compareImages(readPng(reference), readPng(view));
    fmt::print("scene: {} vs {}: max difference {}, PSNR {:.2f} dB, {} pixels differ (threshold PSNR >= {} dB)\n",
               reference, view, d.maxAbs, d.psnr, d.differingPixels, minPsnr);
    return d.psnr >= minPsnr ? 0 : 1;
}

int comparePanel(const std::string& withoutUi, const std::string& withUi, std::uint32_t panelRight)
{
    const penumbra::rhi::Image a = readPng(withoutUi);
    const penumbra::rhi::Image b = readPng(withUi);
    const penumbra::parity::ImageDifference d = penumbra::parity::compareImages(a, b);
    std::size_t outside = 0;
    for (std::uint32_t y = 0; y < a.height; ++y)
        for (std::uint32_t x = panelRight; x < a.width; ++x)
            outside += std::memcmp(a.texel(x, y), b.texel(x, y), 4) != 0;
    fmt::print("panel: {} vs {}: {} pixels differ, {} of them right of x = {}\n", withoutUi, withUi, d.differingPixels,
               outside, panelRight);
    return d.differingPixels > 0 && outside == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const std::string mode = argc == 5 ? argv[1] : "";
        if (mode == "scene")
            return compareScene(argv[2], argv[3], std::atof(argv[4]));
        if (mode == "panel")
            return comparePanel(argv[2], argv[3], std::uint32_t(std::atoi(argv[4])));
        fmt::print(stderr, "usage: compare-screenshots scene|panel <a.png> <b.png> <threshold>\n");
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "compare-screenshots: {}\n", e.what());
        return 1;
    }
}
