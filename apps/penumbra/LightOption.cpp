#include "LightOption.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <sstream>
#include <vector>

namespace penumbra::apps {
namespace {

// The ':'-separated fields of `text`, each a ','-separated list of finite numbers.
std::optional<std::vector<std::vector<float>>> numberFields(const std::string& text)
{
    std::vector<std::vector<float>> fields;
    std::istringstream parts(text);
    for (std::string part; std::getline(parts, part, ':');) {
        std::vector<float>& numbers = fields.emplace_back();
        std::istringstream values(part);
        for (std::string value; std::getline(values, value, ',');) {
            std::size_t used = 0;
            try {
                numbers.push_back(std::stof(value, &used));
            } catch (const std::exception&) {
                return std::nullopt;
            }
            if (used != value.size() || !std::isfinite(numbers.back()))
                return std::nullopt;
        }
    }
    return fields;
}

std::optional<glm::vec3> vec3Of(const std::vector<float>& field)
{
    return field.size() == 3 ? std::optional<glm::vec3>({field[0], field[1], field[2]}) : std::nullopt;
}

std::optional<float> scalarOf(const std::vector<float>& field)
{
    return field.size() == 1 ? std::optional<float>(field[0]) : std::nullopt;
}

// The optional last field: an intensity >= 0, 1 when absent.
std::optional<float> intensityOf(const std::vector<std::vector<float>>& fields, std::size_t index)
{
    if (fields.size() == index)
        return 1.0f;
    const std::optional<float> intensity = fields.size() == index + 1 ? scalarOf(fields[index]) : std::nullopt;
    return intensity && *intensity >= 0.0f ? intensity : std::nullopt;
}

std::optional<glm::vec3> directionOf(const std::vector<float>& field)
{
    const std::optional<glm::vec3> d = vec3Of(field);
    // The length of (1e38, -1, 0) overflows float to infinity and normalizes to (0, -0, 0): a length that is not a
    // finite positive number gives no direction (found by tests/fuzz/FuzzCommandLine.cpp).
    const float length = d ? glm::length(*d) : 0.0f;
    return std::isfinite(length) && length > 0.0f ? std::optional<glm::vec3>(*d / length) : std::nullopt;
}

// What is wrong with the fields of a light of `kind` whose syntax is right, or "": the value and its allowed range.
std::string rangeError(const std::string& kind, const std::vector<std::vector<float>>& f)
{
    const auto checkDirection = [](const std::vector<float>& field) {
        return vec3Of(field) && !directionOf(field) ? fmt::format("the direction {},{},{} has no length (give dx,dy,dz "
                                                                  "not all 0)",
                                                                  field[0], field[1], field[2])
                                                    : std::string();
    };
    const auto checkRange = [](float range) {
        return range > 0.0f ? std::string() : fmt::format("the range {} is not above 0", range);
    };
    const auto checkIntensity = [](const std::vector<std::vector<float>>& fields, std::size_t index) {
        return fields.size() == index + 1 && fields[index].size() == 1 && fields[index][0] < 0.0f
                   ? fmt::format("the intensity {} is below 0", fields[index][0])
                   : std::string();
    };
    std::string error;
    if (kind == "sun") {
        error = checkDirection(f[0]);
        return error.empty() ? checkIntensity(f, 1) : error;
    }
    if (kind == "spot" && f.size() >= 4) {
        if (error = checkDirection(f[1]); !error.empty())
            return error;
        if (f[2].size() == 1 && !(error = checkRange(f[2][0])).empty())
            return error;
        if (f[3].size() == 1 && !(f[3][0] > 0.0f && f[3][0] < kMaxSpotOuterDegrees))
            return fmt::format("the outer cone angle {} degrees is outside (0, {}) (a spot shadow's perspective "
                               "projection needs a cone narrower than a half space)",
                               f[3][0], kMaxSpotOuterDegrees);
        return checkIntensity(f, 4);
    }
    if (kind == "point" && f.size() >= 2) {
        if (f[1].size() == 1 && !(error = checkRange(f[1][0])).empty())
            return error;
        return checkIntensity(f, 2);
    }
    return {};
}

std::optional<LightOption> parseFields(const std::string& kind, const std::vector<std::vector<float>>& f)
{
    if (kind == "sun") {
        const std::optional<glm::vec3> direction = directionOf(f[0]);
        const std::optional<float> intensity = intensityOf(f, 1);
        if (!direction || !intensity)
            return std::nullopt;
        return scene::DirectionalLight{.name = "--light sun", .intensity = *intensity, .direction = *direction};
    }
    if (kind == "spot" && f.size() >= 4) {
        const std::optional<glm::vec3> position = vec3Of(f[0]);
        const std::optional<glm::vec3> direction = directionOf(f[1]);
        const std::optional<float> range = scalarOf(f[2]);
        const std::optional<float> outer = scalarOf(f[3]);
        const std::optional<float> intensity = intensityOf(f, 4);
        if (!position || !direction || !range || !(*range > 0.0f) || !outer ||
            !(*outer > 0.0f && *outer < kMaxSpotOuterDegrees) || !intensity)
            return std::nullopt;
        return scene::SpotLight{.name = "--light spot",
                                .intensity = *intensity,
                                .position = *position,
                                .direction = *direction,
                                .range = *range,
                                .innerAngle = 0.7f * glm::radians(*outer),
                                .outerAngle = glm::radians(*outer)};
    }
    if (kind == "point" && f.size() >= 2) {
        const std::optional<glm::vec3> position = vec3Of(f[0]);
        const std::optional<float> range = scalarOf(f[1]);
        const std::optional<float> intensity = intensityOf(f, 2);
        if (!position || !range || !(*range > 0.0f) || !intensity)
            return std::nullopt;
        return scene::PointLight{.name = "--light point",
                                 .intensity = *intensity,
                                 .position = *position,
                                 .range = *range};
    }
    return std::nullopt;
}

} // namespace

std::optional<LightOption> parseLightOption(const std::string& text, std::string* error)
{
    const std::size_t colon = text.find(':');
    const std::string kind = colon == std::string::npos ? std::string() : text.substr(0, colon);
    const std::optional<std::vector<std::vector<float>>> fields =
        kind.empty() ? std::nullopt : numberFields(text.substr(colon + 1));
    std::optional<LightOption> light =
        fields && !fields->empty() ? parseFields(kind, *fields) : std::optional<LightOption>();
    if (!light && error) {
        const std::string why = fields && !fields->empty() ? rangeError(kind, *fields) : std::string();
        *error = why.empty() ? fmt::format("'{}' is not {}", text, kLightSyntax) : fmt::format("'{}': {}", text, why);
    }
    return light;
}

void addLight(scene::Scene& scene, const LightOption& light)
{
    std::visit(
        [&](const auto& l) {
            using Light = std::decay_t<decltype(l)>;
            if constexpr (std::is_same_v<Light, scene::DirectionalLight>)
                scene.lights.push_back(l);
            else if constexpr (std::is_same_v<Light, scene::SpotLight>)
                scene.spotLights.push_back(l);
            else
                scene.pointLights.push_back(l);
        },
        light);
}

std::optional<AmbientFields> ambientFields(const std::string& text)
{
    std::vector<std::string> parts;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, ':');)
        parts.push_back(part);
    if (parts.size() < 2 || parts.size() > 3 || text.back() == ':')
        return std::nullopt;
    return AmbientFields{"[" + parts[0] + "]", parts[1], parts.size() == 3 ? "[" + parts[2] + "]" : "none"};
}

} // namespace penumbra::apps
