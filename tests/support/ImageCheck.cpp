// The pixel expectations of tests/cli/expect-success.sh: what a written picture shows, not only that it exists.
//   image-check FILE spread MIN                   the luminance of FILE's pixels has a standard deviation above MIN
//   image-check A@REGION darker B@REGION MARGIN   the mean luminance of A's region is below B's by more than MARGIN
//   image-check A@REGION brighter B@REGION MARGIN the same, above
//   image-check FILE depth WxH                    FILE is an EXR of W x H texels with one 32-bit float channel
// Luminance is Rec. 709 luma of the stored values (PNG bytes / 255, EXR's R, G, B as they are); REGION is
// WxH+X+Y in pixels from the top-left corner, the geometry syntax of ImageMagick and oiiotool.
// Prints the measured figures either way; exits 0 when the expectation holds, 1 when not, 2 on bad usage.
#include "penumbra/imageio/ImageFiles.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <fmt/format.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Region {
    int x = 0, y = 0, width = 0, height = 0;
};

// Rec. 709 luma per pixel, row 0 at the top.
struct LumaImage {
    int width = 0, height = 0;
    std::vector<double> luma;
};

LumaImage readLuma(const std::string& file)
{
    LumaImage image;
    if (file.ends_with(".exr")) {
        const penumbra::imageio::FloatImage exr = penumbra::imageio::readExr(file);
        const auto r = exr.channelIndex("R"), g = exr.channelIndex("G"), b = exr.channelIndex("B");
        if (!r || !g || !b)
            throw std::runtime_error(file + ": needs R, G and B channels, has " + std::to_string(exr.channels.size()) +
                                     " channel(s)");
        image = {int(exr.width), int(exr.height), {}};
        for (std::uint32_t y = 0; y < exr.height; ++y)
            for (std::uint32_t x = 0; x < exr.width; ++x)
                image.luma.push_back(0.2126 * exr.at(x, y, *r) + 0.7152 * exr.at(x, y, *g) + 0.0722 * exr.at(x, y, *b));
        return image;
    }
    const penumbra::rhi::Image png = penumbra::imageio::readPng(file);
    image = {int(png.width), int(png.height), {}};
    for (std::size_t i = 0; i < png.bytes.size(); i += 4)
        image.luma.push_back(
            (0.2126 * double(png.bytes[i]) + 0.7152 * double(png.bytes[i + 1]) + 0.0722 * double(png.bytes[i + 2])) /
            255.0);
    return image;
}

struct Luminance {
    double mean = 0.0;
    double deviation = 0.0;
    std::size_t pixels = 0;
};

// All of FILE, or the region after '@'.
Luminance measure(const std::string& argument)
{
    const std::size_t at = argument.find('@');
    const std::string file = argument.substr(0, at);
    const LumaImage image = readLuma(file);
    Region r{0, 0, image.width, image.height};
    if (at != std::string::npos) {
        const std::string geometry = argument.substr(at + 1);
        int end = 0;
        if (std::sscanf(geometry.c_str(), "%dx%d+%d+%d%n", &r.width, &r.height, &r.x, &r.y, &end) != 4 ||
            std::size_t(end) != geometry.size() || r.width <= 0 || r.height <= 0 || r.x < 0 || r.y < 0 ||
            r.x + r.width > image.width || r.y + r.height > image.height)
            throw std::runtime_error(argument + ": region is not WxH+X+Y inside " + std::to_string(image.width) + "x" +
                                     std::to_string(image.height));
    }
    std::vector<double> luma;
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x)
            luma.push_back(image.luma[std::size_t(y) * std::size_t(image.width) + std::size_t(x)]);
    Luminance l;
    l.pixels = luma.size();
    for (double v : luma)
        l.mean += v / double(luma.size());
    for (double v : luma)
        l.deviation += (v - l.mean) * (v - l.mean) / double(luma.size());
    l.deviation = std::sqrt(l.deviation);
    return l;
}

bool check(const std::vector<std::string>& args)
{
    if (args.size() == 3 && args[1] == "spread") {
        const Luminance l = measure(args[0]);
        std::printf("%s: luminance mean %.4f, standard deviation %.4f over %zu pixels (need > %s)\n", args[0].c_str(),
                    l.mean, l.deviation, l.pixels, args[2].c_str());
        return l.deviation > std::stod(args[2]);
    }
    if (args.size() == 4 && (args[1] == "darker" || args[1] == "brighter")) {
        const Luminance a = measure(args[0]), b = measure(args[2]);
        const double margin = std::stod(args[3]);
        std::printf("%s: mean luminance %.4f; %s: %.4f; difference %+.4f (need %s by > %s)\n", args[0].c_str(), a.mean,
                    args[2].c_str(), b.mean, a.mean - b.mean, args[1].c_str(), args[3].c_str());
        return args[1] == "darker" ? a.mean < b.mean - margin : a.mean > b.mean + margin;
    }
    if (args.size() == 3 && args[1] == "depth") {
        const penumbra::imageio::FloatImage depth = penumbra::imageio::readExr(args[0]);
        const std::string found = fmt::format("{}x{}", depth.width, depth.height);
        std::printf("%s: %s with %zu float channel(s) (need %s with 1)\n", args[0].c_str(), found.c_str(),
                    depth.channels.size(), args[2].c_str());
        return found == args[2] && depth.channels.size() == 1;
    }
    throw std::invalid_argument(
        "usage: image-check FILE spread MIN | A@WxH+X+Y darker|brighter B@WxH+X+Y MARGIN | FILE depth WxH");
}

} // namespace

int main(int argc, char** argv)
{
    try {
        return check(std::vector<std::string>(argv + 1, argv + argc)) ? 0 : 1;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "image-check: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "image-check: %s\n", e.what());
        return 1;
    }
}
