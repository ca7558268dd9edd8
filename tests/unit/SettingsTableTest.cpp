// The settings table (penumbra/settings/SettingsTable.hpp) over a settings struct of its own: messages that name
// the field and its allowed values, and a settings file that reads back what it wrote.
#include "penumbra/rhi/Error.hpp"
#include "penumbra/settings/SettingsTable.hpp"

#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <string>

namespace penumbra::settings {
namespace {

enum class ToyMode { Slow, Fast };

struct ToySettings {
    float scale = 1.0f;
    std::uint32_t size = 256;
    ToyMode mode = ToyMode::Slow;
    glm::vec3 tint{1.0f};
    std::optional<glm::vec3> ground;
};

const SettingsTable<ToySettings>& toyTable()
{
    static const SettingsTable<ToySettings> table({
        numeric<ToySettings>(
            "scale", {SettingRangeKind::Closed, 0.5, 2}, "how big", [](auto& s) -> auto& { return s.scale; }),
        numeric<ToySettings>(
            "look.size", {SettingRangeKind::PowersOfTwo, 64, 1024}, "texels per side",
            [](auto& s) -> auto& { return s.size; }),
        named<ToySettings>(
            "look.mode", {nameOf(ToyMode::Slow, "slow"), nameOf(ToyMode::Fast, "fast")}, "how fast",
            [](auto& s) -> auto& { return s.mode; }),
        field<ToySettings>(
            "tint", {SettingRangeKind::AtLeast, 0}, "3 numbers, each at least 0", "a colour",
            [](auto& s) -> auto& { return s.tint; }),
        field<ToySettings>(
            "ground", {SettingRangeKind::AtLeast, 0}, "3 numbers, each at least 0", "an optional colour",
            [](auto& s) -> auto& { return s.ground; }),
    });
    return table;
}

std::string toyError(const std::function<void()>& f)
{
    try {
        f();
    } catch (const rhi::Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(SettingsTable, ABadValueNamesTheFieldAndItsAllowedValues)
{
    ToySettings settings;
    settings.scale = 3.0f;
    EXPECT_EQ(toyError([&] { toyTable().validate(settings); }), "scale: 3 is out of range, allowed 0.5..2");
    ToySettings read;
    EXPECT_EQ(toyError([&] { toyTable().read(R"({"look": {"size": 100}})", "toy.json", read); }),
              "toy.json: look.size: 100 is out of range, allowed powers of two 64..1024");
    EXPECT_EQ(toyError([&] { toyTable().read(R"({"look": {"mode": "medium"}})", "toy.json", read); }),
              "toy.json: look.mode: unknown value \"medium\", allowed slow, fast");
    EXPECT_EQ(toyError([&] { toyTable().read(R"({"tint": [1, -1, 0]})", "toy.json", read); }),
              "toy.json: tint: [1, -1, 0] is out of range, allowed 3 numbers, each at least 0");
    EXPECT_EQ(toyError([&] { toyTable().read(R"({"look": {"speed": 1}})", "toy.json", read); }),
              "toy.json: look.speed: unknown field, allowed size, mode");
    EXPECT_EQ(toyError([&] { toyTable().set(read, "look.size", "48"); }),
              "settings: look.size: 48 is out of range, allowed powers of two 64..1024");
    EXPECT_EQ(read.size, 256u) << "a refused value leaves the settings as they were";
}

TEST(SettingsTable, JsonRoundTripKeepsEveryField)
{
    ToySettings settings;
    toyTable().set(settings, "scale", "0.75");
    toyTable().set(settings, "look.size", "512");
    toyTable().set(settings, "look.mode", "fast");
    toyTable().set(settings, "tint", "[0.5, 0.25, 2]");
    toyTable().set(settings, "ground", "[0, 0.5, 1]");
    const std::string json = toyTable().toJson(settings);
    ToySettings read;
    const std::vector<std::string_view> given = toyTable().read(json, "round-trip", read);
    EXPECT_EQ(given.size(), toyTable().fields().size());
    EXPECT_EQ(read.scale, 0.75f);
    EXPECT_EQ(read.size, 512u);
    EXPECT_EQ(read.mode, ToyMode::Fast);
    EXPECT_EQ(read.tint, glm::vec3(0.5f, 0.25f, 2.0f));
    EXPECT_EQ(read.ground, glm::vec3(0.0f, 0.5f, 1.0f));
    EXPECT_EQ(toyTable().toJson(read), json);
    EXPECT_EQ(toyTable().text(read, "tint"), "[0.5, 0.25, 2]");
}

// An optional field left out reads `none` (text()), and set() takes that word back (the command line's --ambient
// without a ground colour gives it).
TEST(SettingsTable, AnOptionalFieldLeftOutIsSetFromTheWordItIsWrittenAs)
{
    ToySettings settings;
    toyTable().set(settings, "ground", "[0.5, 0.5, 0.5]");
    EXPECT_EQ(settings.ground, glm::vec3(0.5f));
    EXPECT_EQ(toyTable().text(ToySettings{}, "ground"), "none");
    toyTable().set(settings, "ground", "none");
    EXPECT_FALSE(settings.ground.has_value());
    EXPECT_NE(toyError([&] { toyTable().set(settings, "tint", "none"); }), "no error")
        << "a field that is not optional takes no `none`";
}

} // namespace
} // namespace penumbra::settings
