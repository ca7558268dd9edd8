#include "FrameGraph.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

namespace penumbra::render {
namespace {

// A double-quoted dot ID (Graphviz "The DOT Language": IDs).
std::string dotId(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    return out + '"';
}

} // namespace

std::string FrameGraph::dot() const
{
    std::string out =
        "digraph frame {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=11];\n  edge [fontname=\"Helvetica\", fontsize=9];\n";
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        const Resource& resource = resources_[r];
        std::string style = resource.transient ? ", style=filled, fillcolor=\"#dde8f5\"" : "";
        if (resource.output)
            style += ", peripheries=2";
        out += fmt::format("  r{} [shape={}, label={}{}];\n", r, resource.isBuffer ? "cylinder" : "ellipse",
                           dotId(resource.name), style);
    }
    std::size_t order = 0;
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        const Pass& pass = passes_[p];
        std::string label = pass.name;
        std::string style;
        if (!pass.runs) {
            label += "\n(off this frame)";
            style = ", style=dotted, fontcolor=gray50";
        } else if (pass.culled) {
            label += "\n(culled: nothing reads its writes)";
            style = ", style=dashed, fontcolor=gray50";
        } else {
            label = fmt::format("{}. {}", ++order, label);
        }
        out += fmt::format("  p{} [shape=box, label={}{}];\n", p, dotId(label), style);
        for (const Use& use : pass.uses) {
            // The arrow's direction says read or write; only the other uses are named.
            std::vector<std::string> attributes;
            if (pass.culled)
                attributes = {"style=dashed", "color=gray50"};
            if (use.use != ResourceUse::Sampled && use.use != ResourceUse::RenderTarget)
                attributes.push_back("label=" + dotId(resourceUseName(use.use)));
            const std::string list = fmt::format("{}", fmt::join(attributes, ", "));
            if (readsResource(use.use))
                out += fmt::format("  r{} -> p{} [{}];\n", use.resource, p, list);
            if (writesResource(use.use))
                out += fmt::format("  p{} -> r{} [{}];\n", p, use.resource, list);
        }
    }
    // The running order as invisible edges, so the passes line up left to right.
    for (std::size_t p = 1; p < passes_.size(); ++p)
        out += fmt::format("  p{} -> p{} [style=invis, weight=10];\n", p - 1, p);
    return out + "}\n";
}

} // namespace penumbra::render
