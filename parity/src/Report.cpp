#include "penumbra/parity/Report.hpp"

#include "penumbra/parity/HeatMap.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "ReportPage.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <set>

namespace penumbra::parity {
namespace {

// Colour heat maps saturate at this many 8-bit steps, so one-step differences stay visible.
constexpr int kColorHeatScale = 8;
// Depth and float heat maps of pictures that must be identical saturate here.
constexpr float kExactValueHeatScale = 1e-4f;

// JSON has no infinity: identical pictures have PSNR null, unlimited thresholds are null.
nlohmann::json number(double value) { return std::isinf(value) ? nlohmann::json() : nlohmann::json(value); }
nlohmann::json count(std::size_t value) { return value == kAnyCount ? nlohmann::json() : nlohmann::json(value); }

bool writableColor(const rhi::Image& image)
{
    return image.format == rhi::Format::RGBA8 || image.format == rhi::Format::RGBA8_SRGB;
}

// RGBA8 grey of a depth or float picture: near (or large) white, far (or small) black, background black.
rhi::Image greyPicture(const Picture& picture, const rhi::Conventions& conventions)
{
    const ComparableValues v = comparableValues(picture, conventions);
    // FromFarPlane and Given are fractions already; view depth and float values are scaled to their range.
    float low = 0.0f, high = 1.0f;
    const bool scaled = picture.kind == PictureKind::Float || picture.space == DepthSpace::LinearView;
    if (scaled) {
        low = INFINITY;
        high = -INFINITY;
        for (std::size_t i = 0; i < v.values.size(); ++i)
            if (v.drawn[i] && std::isfinite(v.values[i]))
                low = std::min(low, v.values[i]), high = std::max(high, v.values[i]);
    }
    const bool nearIsSmall = picture.kind == PictureKind::Depth && picture.space == DepthSpace::LinearView;
    rhi::Image grey{picture.width(), picture.height(), rhi::Format::RGBA8, std::vector<std::byte>(v.values.size() * 4)};
    for (std::size_t i = 0; i < v.values.size(); ++i) {
        float t = 0.0f;
        if (v.drawn[i] && std::isfinite(v.values[i]))
            t = high > low ? (v.values[i] - low) / (high - low) : 1.0f;
        t = std::clamp(nearIsSmall && v.drawn[i] ? 1.0f - t : t, 0.0f, 1.0f);
        std::fill_n(grey.bytes.begin() + std::ptrdiff_t(i * 4), 3, std::byte(std::lround(t * 255.0f)));
        grey.bytes[i * 4 + 3] = std::byte{255};
    }
    return grey;
}

void writePictures(const std::filesystem::path& folder, const ConfigurationRun& run)
{
    for (const Picture& p : run.pictures) {
        const std::filesystem::path stem = folder / run.name() / p.name;
        if (p.kind == PictureKind::Color) {
            if (writableColor(p.color))
                writePng(stem.string() + ".png", {p.color.width, p.color.height, rhi::Format::RGBA8, p.color.bytes});
            continue;
        }
        writePng(stem.string() + ".png", greyPicture(p, run.conventions()));
        writeExr(stem.string() + ".exr", p.depth);
    }
}

std::string diffStem(const Result& result, const PairResult& pair, const std::string& picture)
{
    return fmt::format("{}-vs-{}-{}", result.configurations[pair.a].name(), result.configurations[pair.b].name(),
                       picture);
}

// Whether a heat map was written: pictures of one size whose difference a heat map can show.
bool writeHeatMap(const std::filesystem::path& folder, const Result& result, const PairResult& pair,
                  const PictureComparison& c)
{
    if (c.figures.pixels == 0)
        return false;
    const ConfigurationRun& a = result.configurations[pair.a];
    const ConfigurationRun& b = result.configurations[pair.b];
    const Picture& pa = a.picture(c.picture);
    const Picture& pb = b.picture(c.picture);
    const std::filesystem::path path = folder / "diff" / (diffStem(result, pair, c.picture) + ".png");
    if (c.kind == PictureKind::Color) {
        if (!writableColor(pa.color))
            return false;
        const auto asRgba8 = [](const rhi::Image& i) {
            return rhi::Image{i.width, i.height, rhi::Format::RGBA8, i.bytes};
        };
        writePng(path, differenceHeatMap(asRgba8(pa.color), asRgba8(pb.color), kColorHeatScale));
        return true;
    }
    const float scale = c.thresholds.maxDifference > 0.0 && std::isfinite(c.thresholds.maxDifference)
                            ? float(c.thresholds.maxDifference)
                            : kExactValueHeatScale;
    writePng(path, differenceHeatMap(comparableValues(pa, a.conventions()).values,
                                     comparableValues(pb, b.conventions()).values, pa.width(), pa.height(), scale));
    return true;
}

const char* statusName(ConfigurationRun::Status status)
{
    switch (status) {
    case ConfigurationRun::Status::Rendered:
        return "rendered";
    case ConfigurationRun::Status::Unsupported:
        return "unsupported";
    case ConfigurationRun::Status::Failed:
        return "failed";
    }
    return "?";
}

nlohmann::json toJson(const Result& result, const std::string& title)
{
    nlohmann::json json;
    json["title"] = title;
    json["configurations"] = nlohmann::json::array();
    for (const ConfigurationRun& run : result.configurations) {
        nlohmann::json c = {{"name", run.name()}, {"status", statusName(run.status)}};
        if (!run.message.empty())
            c["message"] = run.message;
        c["pictures"] = nlohmann::json::array();
        for (const Picture& p : run.pictures)
            c["pictures"].push_back({{"name", p.name}, {"kind", kindName(p.kind)}, {"description", describe(p)}});
        json["configurations"].push_back(c);
    }
    json["pairs"] = nlohmann::json::array();
    for (const PairResult& pair : result.pairs) {
        nlohmann::json p = {{"a", result.configurations[pair.a].name()},
                            {"b", result.configurations[pair.b].name()},
                            {"pictures", nlohmann::json::array()},
                            {"pass", pair.pass()}};
        for (const PictureComparison& c : pair.pictures) {
            const Thresholds& t = c.thresholds;
            nlohmann::json picture = {{"name", c.picture},
                                      {"kind", kindName(c.kind)},
                                      {"maxDifference", number(c.figures.maxDifference)},
                                      {"psnrDb", number(c.figures.psnr)},
                                      {"differingPixels", c.figures.differingPixels},
                                      {"pixels", c.figures.pixels},
                                      {"thresholds",
                                       {{"maxDifference", number(t.maxDifference)},
                                        {"minPsnrDb", t.minPsnr},
                                        {"maxDifferingPixels", count(t.maxDifferingPixels)},
                                        {"ownCheck", bool(t.check)}}},
                                      {"failures", c.failures},
                                      {"pass", c.pass()}};
            if (c.kind == PictureKind::Depth) {
                picture["coverageMismatches"] = c.figures.coverageMismatches;
                picture["thresholds"]["maxCoverageMismatches"] = count(t.maxCoverageMismatches);
                picture["thresholds"]["bitExactWhereConventionsAgree"] = t.bitExactWhereConventionsAgree;
                picture["rawBitIdentical"] = c.figures.rawDifferingTexels
                                                 ? nlohmann::json(*c.figures.rawDifferingTexels == 0)
                                                 : nlohmann::json();
            }
            p["pictures"].push_back(picture);
        }
        json["pairs"].push_back(p);
    }
    json["failures"] = result.failures();
    json["pass"] = result.pass();
    return json;
}

} // namespace

void writeReport(const std::filesystem::path& folder, const Result& result, const std::string& title)
{
    for (const ConfigurationRun& run : result.configurations)
        writePictures(folder, run);
    std::set<std::string> heatMaps;
    for (const PairResult& pair : result.pairs)
        for (const PictureComparison& c : pair.pictures)
            if (writeHeatMap(folder, result, pair, c))
                heatMaps.insert("diff/" + diffStem(result, pair, c.picture) + ".png");
    writeTextFile(folder / "parity.json", toJson(result, title).dump(2) + "\n");
    writeTextFile(folder / "index.html", reportPage(result, title, heatMaps));
}

} // namespace penumbra::parity
