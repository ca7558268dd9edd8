#include "CommandLineSpecs.hpp"

#include <cmath>
#include <cstdio>

namespace penumbra::apps {

std::optional<Size> parseSize(const std::string& text)
{
    unsigned width = 0, height = 0;
    int consumed = 0;
    if (std::sscanf(text.c_str(), "%ux%u%n", &width, &height, &consumed) != 2 || std::size_t(consumed) != text.size())
        return std::nullopt;
    if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize)
        return std::nullopt;
    return Size{width, height};
}

std::optional<LookAt> parseLookAt(const std::string& text)
{
    float v[6];
    int consumed = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f:%f,%f,%f%n", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &consumed) != 6 ||
        std::size_t(consumed) != text.size())
        return std::nullopt;
    for (const float f : v)
        if (!std::isfinite(f))
            return std::nullopt;
    const LookAt lookAt{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    if (lookAt.position == lookAt.target)
        return std::nullopt;
    return lookAt;
}

} // namespace penumbra::apps
