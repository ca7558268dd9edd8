// The pixel expectations of tests/cli/expect-success.sh: what a written picture shows, not only that it exists.
//   image-check FILE spread MIN                   the luminance of FILE's pixels has a standard deviation above MIN
//   image-check A@REGION darker B@REGION MARGIN   the mean luminance of A's region is below B's by more than MARGIN
//   image-check A@REGION brighter B@REGION MARGIN the same, above
// Luminance is Rec. 709 luma of the stored values as OpenImageIO reads them (0..1 for PNG); REGION is
// WxH+X+Y in pixels from the top-left corner, the geometry syntax of oiiotool.
// Prints the measured figures either way; exits 0 when the expectation holds, 1 when not, 2 on bad usage.
#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Region {
    int x = 0, y = 0, width = 0, height = 0;
};

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
    OIIO::ImageBuf image(file);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw std::runtime_error(file + ": " + image.geterror());
    const OIIO::ImageSpec& spec = image.spec();
    if (spec.nchannels < 3)
        throw std::runtime_error(file + ": needs RGB, has " + std::to_string(spec.nchannels) + " channel(s)");
    Region r{0, 0, spec.width, spec.height};
    if (at != std::string::npos) {
        const std::string geometry = argument.substr(at + 1);
        int end = 0;
        if (std::sscanf(geometry.c_str(), "%dx%d+%d+%d%n", &r.width, &r.height, &r.x, &r.y, &end) != 4 ||
            std::size_t(end) != geometry.size() || r.width <= 0 || r.height <= 0 || r.x < 0 || r.y < 0 ||
            r.x + r.width > spec.width || r.y + r.height > spec.height)
            throw std::runtime_error(argument + ": region is not WxH+X+Y inside " + std::to_string(spec.width) + "x" +
                                     std::to_string(spec.height));
    }
    std::vector<double> luma;
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) {
            float rgb[3];
            image.getpixel(x, y, rgb, 3);
            luma.push_back(0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]);
        }
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
    throw std::invalid_argument("usage: image-check FILE spread MIN | A@WxH+X+Y darker|brighter B@WxH+X+Y MARGIN");
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
