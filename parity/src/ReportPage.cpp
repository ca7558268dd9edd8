#include "ReportPage.hpp"

#include <fmt/format.h>

namespace penumbra::parity {
namespace {

// The title, messages and names come from the user; everything else on the page is ours.
std::string escapeHtml(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string thresholdText(const Thresholds& t, PictureKind kind)
{
    std::string text = fmt::format("max diff &le; {:.4g}", t.maxDifference);
    if (t.minPsnr > 0.0)
        text += fmt::format(", PSNR &ge; {} dB", t.minPsnr);
    if (t.maxDifferingPixels != kAnyCount)
        text += fmt::format(", &le; {} pixels differ", t.maxDifferingPixels);
    if (kind == PictureKind::Depth) {
        if (t.maxCoverageMismatches != kAnyCount)
            text += fmt::format(", &le; {} coverage mismatches", t.maxCoverageMismatches);
        if (t.bitExactWhereConventionsAgree)
            text += ", raw bit-exact where conventions agree";
    }
    if (t.check)
        text += ", and a check of the test's own";
    return text;
}

std::string failureList(const std::vector<std::string>& failures)
{
    std::string items;
    for (const std::string& f : failures)
        items += "<li>" + escapeHtml(f) + "</li>";
    return items.empty() ? "" : "<ul class=\"fail\">" + items + "</ul>\n";
}

} // namespace

std::string reportPage(const Result& result, const std::string& title, const std::set<std::string>& heatMaps)
{
    std::string page = fmt::format(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Penumbra parity: {0}</title>\n"
        "<style>body{{font-family:sans-serif}} img{{width:32%;image-rendering:pixelated}} .fail{{color:#c00}} "
        "td,th{{padding:2px 8px;text-align:right}}</style></head><body>\n"
        "<h1>Parity: {0}, {1} configurations</h1>\n<p>{2}</p>\n{3}"
        "<p>Heat maps: black where equal, then red, yellow, white up to 8 steps (colour) or the picture's "
        "largest allowed difference (depth, float), saturated beyond.</p>\n",
        escapeHtml(title), result.configurations.size(), escapeHtml(result.summary()), failureList(result.failures()));
    page += "<table><tr><th>a</th><th>b</th><th>picture</th><th>figures</th><th>thresholds</th><th>result</th></tr>\n";
    for (const PairResult& pair : result.pairs)
        for (const PictureComparison& c : pair.pictures)
            page += fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                                c.pass() ? "" : " class=\"fail\"", result.configurations[pair.a].name(),
                                result.configurations[pair.b].name(), escapeHtml(c.picture), describe(c),
                                thresholdText(c.thresholds, c.kind), c.pass() ? "pass" : "FAIL");
    page += "</table>\n";
    for (const PairResult& pair : result.pairs) {
        const std::string& a = result.configurations[pair.a].name();
        const std::string& b = result.configurations[pair.b].name();
        page += fmt::format("<h2{}>{} vs {}</h2>\n", pair.pass() ? "" : " class=\"fail\"", a, b);
        for (const PictureComparison& c : pair.pictures) {
            const std::string name = escapeHtml(c.picture);
            page += fmt::format("<p{}>{}: {}</p>\n{}", c.pass() ? "" : " class=\"fail\"", name, describe(c),
                                failureList(c.failures));
            const std::string heatMap = fmt::format("diff/{}-vs-{}-{}.png", a, b, c.picture);
            if (heatMaps.count(heatMap))
                page +=
                    fmt::format("<img src=\"{0}/{1}.png\" alt=\"{0} {1}\"> <img src=\"{2}/{1}.png\" alt=\"{2} {1}\"> "
                                "<img src=\"{3}\" alt=\"difference\">\n",
                                a, name, b, heatMap);
        }
    }
    page += "</body></html>\n";
    return page;
}

} // namespace penumbra::parity
