#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <fmt/format.h>
#include <string>

namespace penumbra::shadows {

namespace {

// The Poisson filters' size is their centre tap's bilinear 2.
constexpr std::array<ShadowFilterInfo, kShadowFilterCount> kFilters{{
    {ShadowFilter::PCF2x2, "pcf2x2", "hard", 2, ShadowFilterFamily::Bilinear},
    {ShadowFilter::PCF3x3, "pcf3x3", "pcf3", 3, ShadowFilterFamily::Tent},
    {ShadowFilter::PCF5x5, "pcf5x5", "pcf5", 5, ShadowFilterFamily::Tent},
    {ShadowFilter::PCF7x7, "pcf7x7", "pcf7", 7, ShadowFilterFamily::Tent},
    {ShadowFilter::Poisson, "poisson", "poisson", 2, ShadowFilterFamily::PoissonDisk},
    {ShadowFilter::PCSS, "pcss", "pcss", 2, ShadowFilterFamily::PoissonDisk},
}};

// Each filter at its value's index, the families in order: the shaders tell them apart by comparing a filter with
// the first of a family (PENUMBRA_FILTER_FIRST_POISSON_DISK).
constexpr bool listedInOrder()
{
    for (std::size_t i = 0; i < kFilters.size(); ++i)
        if (static_cast<std::size_t>(kFilters[i].filter) != i || (i > 0 && kFilters[i - 1].family > kFilters[i].family))
            return false;
    return true;
}
static_assert(listedInOrder());

// One kind of the filters' names (JSON or command line), comma separated, in the table's order.
std::string filterNameList(std::string_view ShadowFilterInfo::*name)
{
    std::string text;
    for (const ShadowFilterInfo& entry : kFilters)
        text += fmt::format("{}{}", text.empty() ? "" : ", ", entry.*name);
    return text;
}

} // namespace

const std::array<ShadowFilterInfo, kShadowFilterCount>& shadowFilters() { return kFilters; }

std::optional<ShadowFilter> filterFromCommandName(std::string_view name)
{
    for (const ShadowFilterInfo& entry : shadowFilters())
        if (entry.command == name)
            return entry.filter;
    return std::nullopt;
}

std::string_view filterCommandNames()
{
    static const std::string names = filterNameList(&ShadowFilterInfo::command);
    return names;
}

const std::array<CascadeProjectionName, kCascadeProjectionCount>& cascadeProjectionNames()
{
    static constexpr std::array<CascadeProjectionName, kCascadeProjectionCount> names{{
        {CascadeProjection::Stable, "stable"},
        {CascadeProjection::Close, "close"},
        {CascadeProjection::DepthFit, "depthFit"},
    }};
    return names;
}

std::optional<CascadeProjection> projectionFromName(std::string_view name)
{
    for (const CascadeProjectionName& entry : cascadeProjectionNames())
        if (entry.name == name)
            return entry.projection;
    return std::nullopt;
}

std::string_view projectionNames() { return shadowSettingsField("directional.projection").allowed; }

ShadowFilterFamily filterFamily(ShadowFilter filter)
{
    return shadowFilters()[static_cast<std::size_t>(filter)].family;
}

bool isSoftFilter(ShadowFilter filter) { return filterFamily(filter) == ShadowFilterFamily::PoissonDisk; }

int filterSize(ShadowFilter filter) { return shadowFilters()[static_cast<std::size_t>(filter)].size; }

float normalBiasFilterFactor(ShadowFilter filter)
{
    return isSoftFilter(filter) ? 1.0f : static_cast<float>((filterSize(filter) + 1) / 2);
}

int filterTapCount(ShadowFilter filter)
{
    // An N-wide tent touches N + 1 texels per axis (N odd), read in pairs by bilinear taps.
    const int perAxis = filterFamily(filter) == ShadowFilterFamily::Tent ? (filterSize(filter) + 1) / 2 : 1;
    return perAxis * perAxis;
}

} // namespace penumbra::shadows
