#include "penumbra/shadows/ShadowSettings.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <fmt/format.h>
#include <utility>

namespace penumbra::shadows {

int filterSize(ShadowFilter filter)
{
    constexpr std::array<int, 4> sizes{2, 3, 5, 7};
    return sizes[static_cast<std::size_t>(filter)];
}

float normalBiasFilterFactor(ShadowFilter filter) { return static_cast<float>(static_cast<int>(filter) + 1); }

int filterTapCount(ShadowFilter filter)
{
    // An N-wide tent touches N + 1 texels per axis (N odd), read in pairs by bilinear taps.
    const int perAxis = filter == ShadowFilter::PCF2x2 ? 1 : (filterSize(filter) + 1) / 2;
    return perAxis * perAxis;
}

void validate(const ShadowSettings& settings)
{
    if (const auto problem = detail::findSettingsProblem(settings))
        throw rhi::Error(fmt::format("{}: {}, allowed {}", problem->field, problem->what, problem->allowed));
}

namespace detail {
namespace {

// NaN compares false, so it is never within a range.
bool within(float value, float low, float high) { return value >= low && value <= high; }

SettingsProblem outOfRange(std::string field, std::string value)
{
    std::string allowed(allowedValues(field));
    return {std::move(field), value + " is out of range", std::move(allowed)};
}

} // namespace

std::string_view allowedValues(std::string_view field)
{
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 15> table{{
        {"maxDistance", "> 0.001"},
        {"distanceFade", "0.001..1"},
        {"directional.atlasSize", "powers of two 256..8192"},
        {"directional.filter", "pcf2x2, pcf3x3, pcf5x5, pcf7x7"},
        {"directional.cascadeCount", "1..4"},
        {"directional.cascadeRatios", "3 numbers in 0..1, strictly increasing"},
        {"directional.cascadeFade", "0.001..1"},
        {"directional.cascadeBlend", "hard, soft, dither"},
        {"directional.atlasFormat", "d16, d24s8, d32f"},
        {"other.atlasSize", "powers of two 256..8192"},
        {"other.filter", "pcf2x2, pcf3x3, pcf5x5, pcf7x7"},
        {"other.atlasFormat", "d16, d24s8, d32f"},
        {"other.pointMode", "atlas, cubemap"},
        {"other.cubeMapSize", "powers of two 64..4096"},
        {"other.nearPlane", "0.0001..0.5"},
    }};
    for (const auto& [name, allowed] : table)
        if (name == field)
            return allowed;
    return "";
}

namespace {

bool powerOfTwoWithin(std::uint32_t value, std::uint32_t low, std::uint32_t high)
{
    return (value & (value - 1)) == 0 && value >= low && value <= high;
}

std::optional<SettingsProblem> findOtherSettingsProblem(const OtherShadowSettings& o)
{
    if (!powerOfTwoWithin(o.atlasSize, 256, 8192))
        return outOfRange("other.atlasSize", fmt::format("{}", o.atlasSize));
    if (static_cast<unsigned>(o.filter) > static_cast<unsigned>(ShadowFilter::PCF7x7))
        return outOfRange("other.filter", fmt::format("{}", static_cast<int>(o.filter)));
    if (!rhi::isDepthFormat(o.atlasFormat))
        return outOfRange("other.atlasFormat", std::string(rhi::formatName(o.atlasFormat)));
    if (static_cast<unsigned>(o.pointMode) > static_cast<unsigned>(PointShadowMode::CubeMap))
        return outOfRange("other.pointMode", fmt::format("{}", static_cast<int>(o.pointMode)));
    if (!powerOfTwoWithin(o.cubeMapSize, 64, 4096))
        return outOfRange("other.cubeMapSize", fmt::format("{}", o.cubeMapSize));
    if (!within(o.nearPlane, 0.0001f, 0.5f))
        return outOfRange("other.nearPlane", fmt::format("{}", o.nearPlane));
    return std::nullopt;
}

} // namespace

std::optional<SettingsProblem> findSettingsProblem(const ShadowSettings& s)
{
    const DirectionalShadowSettings& d = s.directional;
    if (!(s.maxDistance > 0.001f))
        return outOfRange("maxDistance", fmt::format("{}", s.maxDistance));
    if (!within(s.distanceFade, 0.001f, 1.0f))
        return outOfRange("distanceFade", fmt::format("{}", s.distanceFade));
    if (!powerOfTwoWithin(d.atlasSize, 256, 8192))
        return outOfRange("directional.atlasSize", fmt::format("{}", d.atlasSize));
    if (static_cast<unsigned>(d.filter) > static_cast<unsigned>(ShadowFilter::PCF7x7))
        return outOfRange("directional.filter", fmt::format("{}", static_cast<int>(d.filter)));
    if (d.cascadeCount < 1 || d.cascadeCount > 4)
        return outOfRange("directional.cascadeCount", fmt::format("{}", d.cascadeCount));
    const glm::vec3 r = d.cascadeRatios;
    if (!within(r.x, 0.0f, 1.0f) || !within(r.y, 0.0f, 1.0f) || !within(r.z, 0.0f, 1.0f) || !(r.x < r.y) ||
        !(r.y < r.z))
        return outOfRange("directional.cascadeRatios", fmt::format("[{}, {}, {}]", r.x, r.y, r.z));
    if (!within(d.cascadeFade, 0.001f, 1.0f))
        return outOfRange("directional.cascadeFade", fmt::format("{}", d.cascadeFade));
    if (static_cast<unsigned>(d.cascadeBlend) > static_cast<unsigned>(CascadeBlend::Dither))
        return outOfRange("directional.cascadeBlend", fmt::format("{}", static_cast<int>(d.cascadeBlend)));
    if (!rhi::isDepthFormat(d.atlasFormat))
        return outOfRange("directional.atlasFormat", std::string(rhi::formatName(d.atlasFormat)));
    return findOtherSettingsProblem(s.other);
}

} // namespace detail
} // namespace penumbra::shadows
