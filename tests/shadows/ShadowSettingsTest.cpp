#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <unistd.h>

namespace penumbra::shadows {
namespace {

void expectEqual(const ShadowSettings& a, const ShadowSettings& b)
{
    EXPECT_EQ(a.maxDistance, b.maxDistance);
    EXPECT_EQ(a.distanceFade, b.distanceFade);
    EXPECT_EQ(a.directional.atlasSize, b.directional.atlasSize);
    EXPECT_EQ(a.directional.filter, b.directional.filter);
    EXPECT_EQ(a.directional.cascadeCount, b.directional.cascadeCount);
    EXPECT_EQ(a.directional.cascadeRatios, b.directional.cascadeRatios);
    EXPECT_EQ(a.directional.cascadeFade, b.directional.cascadeFade);
    EXPECT_EQ(a.directional.cascadeBlend, b.directional.cascadeBlend);
    EXPECT_EQ(a.directional.projection, b.directional.projection);
    EXPECT_EQ(a.directional.depthFitSteps, b.directional.depthFitSteps);
    EXPECT_EQ(a.directional.depthFitHysteresis, b.directional.depthFitHysteresis);
    EXPECT_EQ(a.directional.atlasFormat, b.directional.atlasFormat);
    EXPECT_EQ(a.local.atlasSize, b.local.atlasSize);
    EXPECT_EQ(a.local.filter, b.local.filter);
    EXPECT_EQ(a.local.atlasFormat, b.local.atlasFormat);
    EXPECT_EQ(a.local.pointMode, b.local.pointMode);
    EXPECT_EQ(a.local.cubeMapSize, b.local.cubeMapSize);
    EXPECT_EQ(a.local.nearPlane, b.local.nearPlane);
    EXPECT_EQ(a.directional.depthBias, b.directional.depthBias);
    EXPECT_EQ(a.local.depthBias, b.local.depthBias);
    EXPECT_EQ(a.local.spotFovBias, b.local.spotFovBias);
    EXPECT_EQ(a.local.clusterBuild, b.local.clusterBuild);
    EXPECT_EQ(a.soft.diskRotation, b.soft.diskRotation);
}

ShadowSettings unusualSettings()
{
    ShadowSettings s;
    s.maxDistance = 37.123457f;
    s.distanceFade = 0.333333f;
    s.directional.atlasSize = 4096;
    s.directional.filter = ShadowFilter::PCF5x5;
    s.directional.cascadeCount = 3;
    s.directional.cascadeRatios = {0.05f, 0.3f, 0.71f};
    s.directional.cascadeFade = 0.2f;
    s.directional.cascadeBlend = CascadeBlend::Dither;
    s.directional.projection = CascadeProjection::Close;
    s.directional.depthFitSteps = 16;
    s.directional.depthFitHysteresis = 2.5f;
    s.directional.atlasFormat = rhi::Format::D24S8;
    s.directional.depthBias = 50000.0f;
    s.local.atlasSize = 2048;
    s.local.filter = ShadowFilter::PCF3x3;
    s.local.atlasFormat = rhi::Format::D16;
    s.local.pointMode = PointShadowMode::CubeMap;
    s.local.cubeMapSize = 256;
    s.local.nearPlane = 0.0375f;
    s.local.tileResolution = 256;
    s.local.minTileResolution = 32;
    s.local.depthBias = 2.5f;
    s.local.spotFovBias = Toggle::On;
    s.local.clusterBuild = LightClusterBuild::Gpu;
    s.culling = CasterCullingMode::Gpu;
    s.staticMaps.update = StaticShadowUpdate::OnDemand;
    s.staticMaps.realtimeCasters = RealtimeCasters::Dynamic;
    s.staticMaps.directionalAtlasSize = 8192;
    s.staticMaps.localAtlasSize = 512;
    s.soft = {.blockerSearchScale = 1.5f,
              .penumbraScale = 0.5f,
              .blockerSamples = 32,
              .filterSamples = 64,
              .minPenumbraTexels = 2.0f,
              .maxPenumbraTexels = 30.0f,
              .poissonRadiusTexels = 3.25f,
              .diskRotation = Toggle::Off};
    s.contact = {.shadows = Toggle::On, .length = 0.75f, .steps = 24, .thickness = 0.1f, .localLights = 3};
    return s;
}

// The message of the rhi::Error that `f` throws; fails the test when it throws nothing.
template <typename F>
std::string settingsErrorOf(F&& f)
{
    try {
        f();
    } catch (const rhi::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no rhi::Error thrown";
    return "";
}

std::string validationError(void (*change)(ShadowSettings&))
{
    ShadowSettings s;
    change(s);
    return settingsErrorOf([&] { validate(s); });
}

TEST(ShadowSettings, DefaultsAreValid)
{
    EXPECT_NO_THROW(validate(ShadowSettings{}));
    EXPECT_NO_THROW(validate(unusualSettings()));
}

TEST(ShadowSettings, ValidationNamesTheFieldTheValueAndTheRange)
{
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.directional.cascadeCount = 5; }),
              "directional.cascadeCount: 5 is out of range, allowed 1..4");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.directional.atlasSize = 1000; }),
              "directional.atlasSize: 1000 is out of range, allowed powers of two 256..8192");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.directional.atlasSize = 16384; }),
              "directional.atlasSize: 16384 is out of range, allowed powers of two 256..8192");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.directional.projection = CascadeProjection(3); }),
              "directional.projection: 3 is out of range, allowed stable, close, depthFit");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.contact.steps = 0; }),
              "contact.steps: 0 is out of range, allowed 1..64");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.contact.localLights = 5; }),
              "contact.localLights: 5 is out of range, allowed 0..4");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.maxDistance = 0.0f; }),
              "maxDistance: 0 is out of range, allowed > 0.001");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.distanceFade = 1.5f; }),
              "distanceFade: 1.5 is out of range, allowed 0.001..1");
    EXPECT_EQ(validationError([](ShadowSettings& s) {
                  s.directional.cascadeRatios = {0.1f, 0.5f, 0.5f};
              }),
              "directional.cascadeRatios: [0.1, 0.5, 0.5] is out of range, allowed 3 numbers in 0..1, strictly "
              "increasing");
    EXPECT_EQ(validationError([](ShadowSettings& s) { s.directional.cascadeFade = std::nanf(""); }),
              "directional.cascadeFade: nan is out of range, allowed 0.001..1");
    EXPECT_EQ(validationError([](ShadowSettings& s) {
                  s.directional.atlasFormat = rhi::Format::RGBA8;
              }).rfind("directional.atlasFormat: ", 0),
              0u);
}

// The design documents' constant biases (Catlike Coding's "Directional Shadows", section 4.1: 50 000 and 500 000) are
// accepted; the toggles are named off and on.
TEST(ShadowSettingsJson, TheDocumentsDepthBiasesAndTheTogglesAreAccepted)
{
    ShadowSettings settings;
    setSettingsField(settings, "directional.depthBias", "500000");
    setSettingsField(settings, "local.depthBias", "50000");
    setSettingsField(settings, "local.spotFovBias", "on");
    setSettingsField(settings, "soft.diskRotation", "off");
    EXPECT_EQ(settings.directional.depthBias, 500000.0f);
    EXPECT_EQ(settings.local.depthBias, 50000.0f);
    EXPECT_EQ(settings.local.spotFovBias, Toggle::On);
    EXPECT_EQ(settings.soft.diskRotation, Toggle::Off);
    EXPECT_EQ(settingsFieldText(ShadowSettings{}, "local.spotFovBias"), "off");
    EXPECT_EQ(settingsFieldText(ShadowSettings{}, "soft.diskRotation"), "on");
    EXPECT_THROW(setSettingsField(settings, "local.depthBias", "-1"), rhi::Error);
    EXPECT_THROW(setSettingsField(settings, "soft.diskRotation", "yes"), rhi::Error);
}

// The tool's options set a field by its path and text, and its range comes from the one table.
TEST(ShadowSettingsJson, FieldsAreSetByPathAndCheckedByTheirRange)
{
    ShadowSettings settings;
    setSettingsField(settings, "directional.projection", "close");
    setSettingsField(settings, "static.localAtlasSize", "512");
    EXPECT_EQ(settings.directional.projection, CascadeProjection::Close);
    EXPECT_EQ(settings.staticMaps.localAtlasSize, 512u);
    EXPECT_EQ(settingsFieldText(settings, "directional.projection"), "close");
    EXPECT_EQ(settingsFieldText(ShadowSettings{}, "directional.cascadeRatios"), "[0.1, 0.25, 0.5]");
    EXPECT_THROW(setSettingsField(settings, "directional.projection", "tight"), rhi::Error);
    EXPECT_THROW(setSettingsField(settings, "static.localAtlasSize", "384"), rhi::Error);
    EXPECT_EQ(settings.staticMaps.localAtlasSize, 512u);
    EXPECT_EQ(shadowSettingsField("local.atlasSize").allowed, "powers of two 256..8192");
    EXPECT_TRUE(withinRange(shadowSettingsField("local.nearPlane").range, 0.0001f));
    EXPECT_FALSE(withinRange(shadowSettingsField("maxDistance").range, 0.001f));
}

TEST(ShadowSettingsJson, RoundTripKeepsEveryField)
{
    for (const ShadowSettings& s : {ShadowSettings{}, unusualSettings()}) {
        const std::string json = toJson(s);
        expectEqual(parseShadowSettings(json, "round-trip"), s);
        EXPECT_EQ(toJson(parseShadowSettings(json, "round-trip")), json);
    }
    const std::string json = toJson(unusualSettings());
    EXPECT_NE(json.find("\"filter\": \"pcf5x5\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"cascadeBlend\": \"dither\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"projection\": \"close\""), std::string::npos) << json;
    EXPECT_NE(toJson(ShadowSettings{}).find("\"projection\": \"stable\""), std::string::npos);
    EXPECT_NE(json.find("\"atlasFormat\": \"d24s8\""), std::string::npos) << json;
}

// Every field of the table moves through its text, and the settings file holds exactly the table's fields.
TEST(ShadowSettingsJson, EveryFieldOfTheTableRoundTripsThroughItsText)
{
    const ShadowSettings unusual = unusualSettings();
    ShadowSettings copy;
    for (const ShadowSettingsField& field : shadowSettingsFields()) {
        EXPECT_NE(settingsFieldText(unusual, field.path), settingsFieldText(ShadowSettings{}, field.path))
            << field.path << " keeps its default in unusualSettings: the loop would prove nothing for it";
        setSettingsField(copy, field.path, settingsFieldText(unusual, field.path));
    }
    EXPECT_EQ(toJson(copy), toJson(unusual));
}

TEST(ShadowSettingsJson, MissingFieldsKeepTheirDefaults)
{
    expectEqual(parseShadowSettings("{}", "empty.json"), ShadowSettings{});
    ShadowSettings expected;
    expected.directional.cascadeCount = 2;
    expected.directional.filter = ShadowFilter::PCF7x7;
    expectEqual(parseShadowSettings(R"({"directional": {"cascadeCount": 2, "filter": "pcf7x7"}})", "some.json"),
                expected);
}

TEST(ShadowSettingsJson, OldNamesOfTheLocalFieldsStillLoad)
{
    ShadowSettings expected;
    expected.local.atlasSize = 1024;
    expected.local.pointMode = PointShadowMode::CubeMap;
    expected.staticMaps.localAtlasSize = 512;
    const char* current =
        R"({"local": {"atlasSize": 1024, "pointMode": "cubemap"}, "static": {"localAtlasSize": 512}})";
    const char* old = R"({"other": {"atlasSize": 1024, "pointMode": "cubemap"}, "static": {"otherAtlasSize": 512}})";
    expectEqual(parseShadowSettings(current, "current.json"), expected);
    expectEqual(parseShadowSettings(old, "old.json"), expected);
    EXPECT_EQ(toJson(parseShadowSettings(old, "old.json")), toJson(expected));
}

TEST(ShadowSettingsJson, BothNamesOfALocalFieldAreRefused)
{
    EXPECT_EQ(settingsErrorOf([] { parseShadowSettings(R"({"local": {}, "other": {}})", "both.json"); }),
              "both.json: other and local are one field (the old and the current name); give only local");
    EXPECT_EQ(settingsErrorOf([] {
                  parseShadowSettings(R"({"static": {"otherAtlasSize": 512, "localAtlasSize": 512}})", "both.json");
              }),
              "both.json: static.otherAtlasSize and static.localAtlasSize are one field (the old and the current "
              "name); give only static.localAtlasSize");
}

TEST(ShadowSettingsJson, ErrorsNameTheSourceTheFieldAndTheRange)
{
    auto parseError = [](const char* json) {
        return settingsErrorOf([&] { parseShadowSettings(json, "shadows.json"); });
    };
    EXPECT_EQ(
        parseError(R"({"maxDistanse": 5})"),
        "shadows.json: maxDistanse: unknown field, allowed maxDistance, distanceFade, culling, directional, local, soft, "
        "static, contact");
    EXPECT_EQ(parseError(R"({"static": {"update": "sometimes"}})"),
              "shadows.json: static.update: unknown value \"sometimes\", allowed everyFrame, onChange, onDemand");
    EXPECT_EQ(parseError(R"({"static": {"directionalAtlasSize": 16384}})"),
              "shadows.json: static.directionalAtlasSize: 16384 is out of range, allowed powers of two 256..8192");
    EXPECT_EQ(parseError(R"({"local": {"pointMode": "cube"}})"),
              "shadows.json: local.pointMode: unknown value \"cube\", allowed atlas, cubemap");
    EXPECT_EQ(parseError(R"({"local": {"atlasSize": 100}})"),
              "shadows.json: local.atlasSize: 100 is out of range, allowed powers of two 256..8192");
    EXPECT_EQ(parseError(R"({"local": {"cubeMapSize": 8192}})"),
              "shadows.json: local.cubeMapSize: 8192 is out of range, allowed powers of two 64..4096");
    EXPECT_EQ(parseError(R"({"local": {"nearPlane": 0.6}})"),
              "shadows.json: local.nearPlane: 0.6 is out of range, allowed 0.0001..0.5");
    EXPECT_EQ(parseError(R"({"directional": {"blend": "soft"}})"),
              "shadows.json: directional.blend: unknown field, allowed atlasSize, filter, cascadeCount, "
              "cascadeRatios, cascadeFade, cascadeBlend, projection, depthFitSteps, depthFitHysteresis, atlasFormat, "
              "depthBias");
    EXPECT_EQ(parseError(R"({"directional": {"projection": "tight"}})"),
              "shadows.json: directional.projection: unknown value \"tight\", allowed stable, close, depthFit");
    EXPECT_EQ(parseError(R"({"directional": {"projection": 1}})"),
              "shadows.json: directional.projection: unknown value 1, allowed stable, close, depthFit");
    // Found by the shadow_settings fuzz target: nlohmann reports a number beyond double as out_of_range, not as a
    // parse error; it is bad JSON like any other (tests/fuzz/regressions/shadow_settings/).
    const std::string overflow = parseError(R"({"maxDistance": 1e382})");
    EXPECT_EQ(overflow.rfind("shadows.json: not valid JSON: ", 0), 0u) << overflow;
    EXPECT_NE(overflow.find("number overflow"), std::string::npos) << overflow;
    EXPECT_EQ(parseError(R"({"maxDistance": "far"})"),
              "shadows.json: maxDistance: expected a number, got \"far\", allowed > 0.001");
    EXPECT_EQ(parseError(R"({"directional": {"cascadeCount": 2.5}})"),
              "shadows.json: directional.cascadeCount: expected an integer, got 2.5, allowed 1..4");
    EXPECT_EQ(parseError(R"({"directional": {"cascadeCount": 9}})"),
              "shadows.json: directional.cascadeCount: 9 is out of range, allowed 1..4");
    EXPECT_EQ(
        parseError(R"({"directional": {"filter": "pcf4x4"}})"),
        "shadows.json: directional.filter: unknown value \"pcf4x4\", allowed pcf2x2, pcf3x3, pcf5x5, pcf7x7, poisson, pcss");
    EXPECT_EQ(parseError(R"({"directional": {"cascadeBlend": "Soft"}})"),
              "shadows.json: directional.cascadeBlend: unknown value \"Soft\", allowed hard, soft, dither");
    EXPECT_EQ(parseError(R"({"directional": {"atlasFormat": "rgba8"}})"),
              "shadows.json: directional.atlasFormat: unknown value \"rgba8\", allowed d16, d24s8, d32f");
    EXPECT_EQ(parseError(R"({"directional": {"cascadeRatios": [0.1, 0.2]}})"),
              "shadows.json: directional.cascadeRatios: expected an array of 3 numbers, got [0.1,0.2], allowed 3 "
              "numbers in 0..1, strictly increasing");
    EXPECT_EQ(parseError(R"({"directional": 4})"), "shadows.json: directional: expected an object, got 4");
    EXPECT_EQ(parseError(R"({"maxDistance": 1e300})"),
              "shadows.json: maxDistance: 1e+300 is out of range, allowed > 0.001");
    EXPECT_EQ(parseError(R"({"directional": {"atlasSize": -512}})"),
              "shadows.json: directional.atlasSize: -512 is out of range, allowed powers of two 256..8192");
    EXPECT_EQ(parseError("{\"maxDistance\": 10,").rfind("shadows.json: not valid JSON: ", 0), 0u);
}

class ShadowSettingsFile : public ::testing::Test {
protected:
    std::filesystem::path directory =
        std::filesystem::temp_directory_path() / ("penumbra-shadow-settings-" + std::to_string(::getpid()));

    void SetUp() override { std::filesystem::create_directories(directory); }
    void TearDown() override { std::filesystem::remove_all(directory); }

    std::size_t fileCount() const
    {
        return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(directory), {}));
    }
};

TEST_F(ShadowSettingsFile, SaveThenLoadGivesTheSameSettings)
{
    const std::filesystem::path path = directory / "shadows.json";
    saveShadowSettings(path, unusualSettings());
    expectEqual(loadShadowSettings(path), unusualSettings());
    saveShadowSettings(path, ShadowSettings{}); // replaces the existing file
    expectEqual(loadShadowSettings(path), ShadowSettings{});
    EXPECT_EQ(fileCount(), 1u); // no temporary left behind
}

TEST_F(ShadowSettingsFile, FailedSaveLeavesTheOldFileWhole)
{
    const std::filesystem::path path = directory / "shadows.json";
    saveShadowSettings(path, unusualSettings());
    ShadowSettings invalid;
    invalid.directional.cascadeCount = 0;
    EXPECT_THROW(saveShadowSettings(path, invalid), rhi::Error);
    // Missing folders are made (rhi::writeFileAtomically); one below a file cannot be.
    EXPECT_THROW(saveShadowSettings(path / "below-a-file" / "shadows.json", ShadowSettings{}), rhi::Error);
    expectEqual(loadShadowSettings(path), unusualSettings());
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(ShadowSettingsFile, LoadErrorsNameThePath)
{
    const std::filesystem::path missing = directory / "nothing.json";
    EXPECT_NE(settingsErrorOf([&] { loadShadowSettings(missing); }).find(missing.string()), std::string::npos);
    const std::filesystem::path bad = directory / "bad.json";
    std::ofstream(bad) << R"({"directional": {"cascadeCount": 7}})";
    EXPECT_EQ(settingsErrorOf([&] { loadShadowSettings(bad); }),
              bad.string() + ": directional.cascadeCount: 7 is out of range, allowed 1..4");
}

} // namespace
} // namespace penumbra::shadows
