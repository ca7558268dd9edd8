#include "penumbra/parity/HeatMap.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "ParityReport.hpp"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace penumbra::apps {
namespace {

// Lit heat maps saturate at this many 8-bit steps, so one-step differences stay visible.
constexpr int kLitHeatScale = 8;

// JSON has no infinity: identical pictures have PSNR null.
nlohmann::json psnr(double value) { return std::isinf(value) ? nlohmann::json() : nlohmann::json(value); }

std::string pairStem(const PairParity& pair, const std::vector<ShadowPictures>& pictures)
{
    return fmt::format("{}-vs-{}", pictures[pair.a].configuration, pictures[pair.b].configuration);
}

nlohmann::json toJson(const ParityReport& report, const std::vector<ShadowPictures>& pictures,
                      const std::string& sceneName)
{
    nlohmann::json json;
    json["scene"] = sceneName;
    json["size"] = {pictures.front().lit.width, pictures.front().lit.height};
    json["thresholds"] = {{"litMinPsnrDb", report.thresholds.minLitPsnr},
                          {"atlasMaxLightDepthDifference", report.thresholds.maxLightDepthDifference},
                          {"pattern", "byte-identical"}};
    json["configurations"] = nlohmann::json::array();
    for (std::size_t i = 0; i < pictures.size(); ++i) {
        nlohmann::json c = {{"name", pictures[i].configuration}};
        if (i < report.patternIdentical.size())
            c["patternIdenticalToFirst"] = bool(report.patternIdentical[i]);
        json["configurations"].push_back(c);
    }
    json["pairs"] = nlohmann::json::array();
    for (const PairParity& pair : report.pairs) {
        nlohmann::json p = {{"a", pictures[pair.a].configuration},
                            {"b", pictures[pair.b].configuration},
                            {"lit",
                             {{"maxAbs", pair.lit.maxAbs},
                              {"psnrDb", psnr(pair.lit.psnr)},
                              {"differingPixels", pair.lit.differingPixels},
                              {"pass", pair.lit.psnr >= report.thresholds.minLitPsnr}}},
                            {"atlases", nlohmann::json::array()},
                            {"pass", pair.pass}};
        for (const AtlasParity& atlas : pair.atlases)
            p["atlases"].push_back({{"name", atlas.name},
                                    {"lightDepthMaxAbs", atlas.lightDepth.maxAbs},
                                    {"lightDepthPsnrDb", psnr(atlas.lightDepth.psnr)},
                                    {"differingTexels", atlas.lightDepth.differingPixels},
                                    {"rawBitIdentical", atlas.rawIdentical ? nlohmann::json(*atlas.rawIdentical)
                                                                           : nlohmann::json()},
                                    {"pass", atlas.pass}});
        json["pairs"].push_back(p);
    }
    json["pass"] = report.pass;
    return json;
}

// The scene's name is a user's path; everything else on the page is ours.
std::string escapeHtml(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string figure(double psnrDb) { return std::isinf(psnrDb) ? "identical" : fmt::format("{:.1f} dB", psnrDb); }

std::string html(const ParityReport& report, const std::vector<ShadowPictures>& pictures, const std::string& sceneName)
{
    std::string page = fmt::format(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Penumbra parity: {0}</title>\n"
        "<style>body{{font-family:sans-serif}} img{{width:32%;image-rendering:pixelated}} .fail{{color:#c00}} "
        "td,th{{padding:2px 8px;text-align:right}}</style></head><body>\n"
        "<h1>Parity: {0}, {1} configurations</h1>\n<p>{2}</p>\n"
        "<p>Thresholds: lit PSNR &ge; {3} dB; atlas light-depth difference &le; {4:g}; test patterns byte-identical. "
        "Heat maps: black where equal, then red, yellow, white up to {5} 8-bit steps (lit) or the light-depth "
        "threshold (atlas), saturated beyond.</p>\n",
        escapeHtml(sceneName), pictures.size(), report.summary(pictures), report.thresholds.minLitPsnr,
        report.thresholds.maxLightDepthDifference, kLitHeatScale);
    page += "<table><tr><th>a</th><th>b</th><th>lit max</th><th>lit PSNR</th><th>lit pixels differing</th>"
            "<th>atlas light-depth max</th><th>atlas raw</th><th>result</th></tr>\n";
    for (const PairParity& pair : report.pairs) {
        std::string atlasMax, raw;
        for (const AtlasParity& atlas : pair.atlases) {
            atlasMax += fmt::format("{}: {:.3g} ", atlas.name, atlas.lightDepth.maxAbs);
            raw += atlas.rawIdentical ? (*atlas.rawIdentical ? "bit-identical " : "differs ") : "other conventions ";
        }
        page += fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
                            "<td>{}</td></tr>\n",
                            pair.pass ? "" : " class=\"fail\"", pictures[pair.a].configuration,
                            pictures[pair.b].configuration, pair.lit.maxAbs, figure(pair.lit.psnr),
                            pair.lit.differingPixels, atlasMax, raw, pair.pass ? "pass" : "FAIL");
    }
    page += "</table>\n";
    for (const PairParity& pair : report.pairs) {
        const std::string& a = pictures[pair.a].configuration;
        const std::string& b = pictures[pair.b].configuration;
        const std::string stem = pairStem(pair, pictures);
        page += fmt::format("<h2{}>{} vs {}</h2>\n<p>lit: {}, {} pixels differ</p>\n"
                            "<img src=\"{}/lit.png\" alt=\"{} lit\"> <img src=\"{}/lit.png\" alt=\"{} lit\"> "
                            "<img src=\"diff/{}-lit.png\" alt=\"difference\">\n",
                            pair.pass ? "" : " class=\"fail\"", a, b, figure(pair.lit.psnr),
                            pair.lit.differingPixels, a, a, b, b, stem);
        for (const AtlasParity& atlas : pair.atlases)
            page += fmt::format("<p>{} atlas: light-depth max {:.3g}, {} texels differ</p>\n"
                                "<img src=\"{}/{}.png\" alt=\"{} atlas\"> <img src=\"{}/{}.png\" alt=\"{} atlas\"> "
                                "<img src=\"diff/{}-{}.png\" alt=\"difference\">\n",
                                atlas.name, atlas.lightDepth.maxAbs, atlas.lightDepth.differingPixels, a,
                                atlasFileStem(atlas.name), a, b, atlasFileStem(atlas.name), b, stem, atlas.name);
    }
    page += "</body></html>\n";
    return page;
}

} // namespace

void writeParityReport(const std::filesystem::path& folder, const ParityReport& report,
                       const std::vector<ShadowPictures>& pictures, const std::string& sceneName)
{
    for (const PairParity& pair : report.pairs) {
        const ShadowPictures& a = pictures[pair.a];
        const ShadowPictures& b = pictures[pair.b];
        const std::filesystem::path stem = folder / "diff" / pairStem(pair, pictures);
        parity::writePng(stem.string() + "-lit.png", parity::differenceHeatMap(a.lit, b.lit, kLitHeatScale));
        for (const AtlasPictures& atlas : a.atlases)
            parity::writePng(fmt::format("{}-{}.png", stem.string(), atlas.name),
                     parity::differenceHeatMap(atlas.lightDepth, b.atlas(atlas.name).lightDepth, atlas.depth.width,
                                       atlas.depth.height, report.thresholds.maxLightDepthDifference));
    }
    parity::writeTextFile(folder / "parity.json", toJson(report, pictures, sceneName).dump(2) + "\n");
    parity::writeTextFile(folder / "index.html", html(report, pictures, sceneName));
}

} // namespace penumbra::apps
