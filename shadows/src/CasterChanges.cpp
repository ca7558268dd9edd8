#include "penumbra/shadows/CasterChanges.hpp"

#include <algorithm>

namespace penumbra::shadows {

void CasterChanges::changedAll()
{
    open_.all = true;
    open_.indices.clear();
}

void CasterChanges::changed(std::uint32_t index)
{
    if (!open_.all)
        open_.indices.push_back(index);
}

void CasterChanges::advance()
{
    std::sort(open_.indices.begin(), open_.indices.end());
    open_.indices.erase(std::unique(open_.indices.begin(), open_.indices.end()), open_.indices.end());
    generation_ = open_.number;
    // The oldest kept generation's storage serves the next one, so that a steady frame allocates nothing.
    Generation next;
    if (kept_.size() == kKeptGenerations) {
        next = std::move(kept_.front());
        kept_.pop_front();
    }
    kept_.push_back(std::move(open_));
    next.number = generation_ + 1;
    next.all = false;
    next.indices.clear();
    open_ = std::move(next);
}

std::optional<std::vector<CasterRange>> CasterChanges::since(std::optional<std::uint64_t> seen) const
{
    if (!seen || kept_.empty() || *seen + 1 < kept_.front().number || *seen > generation_)
        return std::nullopt;
    std::vector<std::uint32_t> indices;
    for (const Generation& generation : kept_) {
        if (generation.number <= *seen)
            continue;
        if (generation.all)
            return std::nullopt;
        indices.insert(indices.end(), generation.indices.begin(), generation.indices.end());
    }
    std::sort(indices.begin(), indices.end());
    std::vector<CasterRange> ranges;
    for (const std::uint32_t index : indices) {
        if (!ranges.empty() && index < ranges.back().first + ranges.back().count)
            continue;
        if (!ranges.empty() && index == ranges.back().first + ranges.back().count)
            ++ranges.back().count;
        else
            ranges.push_back({index, 1});
    }
    return ranges;
}

} // namespace penumbra::shadows
