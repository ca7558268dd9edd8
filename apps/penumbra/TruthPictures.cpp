#include "TruthPictures.hpp"

#include "penumbra/parity/ImageFiles.hpp"

#include "penumbra/rhi/Image.hpp"

#include <array>
#include <fmt/format.h>
#include <optional>
#include <span>

namespace penumbra::apps {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kBackground{0, 0, 0};
constexpr Rgb kNoLight{28, 28, 40}; // a surface no compared light decides
constexpr Rgb kAcne{235, 40, 40};
constexpr Rgb kLeak{40, 100, 255};
constexpr Rgb kAcneAndLeak{220, 40, 220};
constexpr Rgb kNearEdge{70, 58, 30}; // dark amber: left out, neither right nor wrong
constexpr Rgb kLitRight{180, 180, 180};
constexpr Rgb kShadowedRight{90, 90, 90};
constexpr Rgb kDithered{60, 130, 110}; // teal: behind dithered casters only, compared on average

Rgb grey(float visibility)
{
    const auto level = static_cast<std::uint8_t>(40.0f + 190.0f * visibility + 0.5f);
    return {level, level, level};
}

// A picture of width x height from colour(pixel index).
template <typename Colour>
rhi::Image picture(std::uint32_t width, std::uint32_t height, Colour colour)
{
    rhi::Image image{width, height, rhi::Format::RGBA8, std::vector<std::byte>(std::size_t(width) * height * 4)};
    for (std::size_t i = 0; i < std::size_t(width) * height; ++i) {
        const Rgb c = colour(i);
        for (std::size_t k = 0; k < 3; ++k)
            image.bytes[4 * i + k] = std::byte(c[k]);
        image.bytes[4 * i + 3] = std::byte(255);
    }
    return image;
}

bool isSurface(const LightTruth& t, std::size_t i) { return t.raycast.pixels[i] != truth::LightVisibility::Background; }

// Grey by the mean of visibilityOf(light, pixel) over the lights that decide the pixel (nullopt: undecided).
template <typename VisibilityOf>
rhi::Image meanVisibilityPicture(std::span<const LightTruth> lights, VisibilityOf visibilityOf)
{
    const truth::LightVisibilityMask& first = lights.front().raycast;
    return picture(first.width, first.height, [&](std::size_t i) {
        float seen = 0.0f;
        int decided = 0;
        for (const LightTruth& t : lights)
            if (const std::optional<float> v = visibilityOf(t, i)) {
                seen += *v;
                ++decided;
            }
        if (decided == 0)
            return isSurface(lights.front(), i) ? kNoLight : kBackground;
        return grey(seen / float(decided));
    });
}

rhi::Image raycastPicture(std::span<const LightTruth> lights)
{
    return meanVisibilityPicture(lights, [](const LightTruth& t, std::size_t i) -> std::optional<float> {
        switch (t.raycast.pixels[i]) {
        case truth::LightVisibility::Lit:
            return 1.0f;
        case truth::LightVisibility::Shadowed:
            return 0.0f;
        case truth::LightVisibility::Dithered:
            return 1.0f - t.raycast.ditherCoverage[i];
        case truth::LightVisibility::Background:
        case truth::LightVisibility::FacingAway:
        case truth::LightVisibility::NotReceiving:
            return std::nullopt;
        }
        return std::nullopt;
    });
}

rhi::Image shadowMapPicture(std::span<const LightTruth> lights)
{
    return meanVisibilityPicture(lights, [](const LightTruth& t, std::size_t i) -> std::optional<float> {
        return t.rendered.decided[i] ? std::optional<float>(t.rendered.lit[i]) : std::nullopt;
    });
}

rhi::Image disagreementPicture(std::span<const LightTruth> lights)
{
    const truth::TruthComparison& first = lights.front().comparison;
    return picture(first.width, first.height, [&](std::size_t i) {
        bool acne = false, leak = false, edge = false, lit = false, shadowed = false, dithered = false;
        for (const LightTruth& t : lights) {
            const truth::TruthVerdict v = t.comparison.verdicts[i];
            acne |= v == truth::TruthVerdict::Acne;
            leak |= v == truth::TruthVerdict::Leak;
            edge |= v == truth::TruthVerdict::NearEdge;
            lit |= v == truth::TruthVerdict::LitRight;
            shadowed |= v == truth::TruthVerdict::ShadowedRight;
            dithered |= v == truth::TruthVerdict::Dithered;
        }
        if (acne || leak)
            return acne && leak ? kAcneAndLeak : acne ? kAcne : kLeak;
        if (edge)
            return kNearEdge;
        if (lit || shadowed)
            return lit ? kLitRight : kShadowedRight;
        if (dithered)
            return kDithered;
        return isSurface(lights.front(), i) ? kNoLight : kBackground;
    });
}

void writeSet(const std::filesystem::path& folder, std::span<const LightTruth> lights, const std::string& suffix)
{
    parity::writePng(folder / fmt::format("raycast{}.png", suffix), raycastPicture(lights));
    parity::writePng(folder / fmt::format("shadowmap{}.png", suffix), shadowMapPicture(lights));
    parity::writePng(folder / fmt::format("disagreement{}.png", suffix), disagreementPicture(lights));
}

} // namespace

void writeTruthPictures(const std::filesystem::path& folder, const std::vector<LightTruth>& lights)
{
    writeSet(folder, lights, "");
    if (lights.size() > 1)
        for (std::size_t n = 0; n < lights.size(); ++n)
            writeSet(folder, std::span(lights).subspan(n, 1), fmt::format("-{}", n + 1));
}

} // namespace penumbra::apps
