#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace penumbra::shadows {

// Casters [first, first + count).
struct CasterRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool operator==(const CasterRange&) const = default;
};

// Which casters changed, update by update, so that what keeps the casters resident (the GPU culling pass's storage)
// rewrites only those instead of every caster every frame. Each update of the caster list is a generation; a consumer
// remembers the generation it read last and asks what changed since. A consumer that skipped more generations than
// are kept, or whose casters were rebuilt since, reads them all again.
class CasterChanges {
public:
    // Generations whose changes are kept: a consumer that reads every frame or every few frames gets ranges.
    static constexpr std::size_t kKeptGenerations = 8;

    // Every caster changed in this generation (the list was built anew).
    void changedAll();
    // Caster `index` changed in this generation.
    void changed(std::uint32_t index);
    // Closes this generation: the next changes belong to a new one, whose number generation() then returns.
    void advance();
    // The number of the latest closed generation (0 before the first advance()).
    std::uint64_t generation() const { return generation_; }

    // The casters changed in the generations after `seen` up to generation(), as ascending disjoint ranges (empty
    // where nothing changed), or nullopt where everything must be read again: all changed since, `seen` is older
    // than the kept generations, or nullopt (nothing read yet).
    std::optional<std::vector<CasterRange>> since(std::optional<std::uint64_t> seen) const;

private:
    struct Generation {
        std::uint64_t number = 0;
        bool all = false;
        std::vector<std::uint32_t> indices; // ascending, unique
    };
    std::deque<Generation> kept_; // the closed generations, oldest first
    Generation open_{1, true, {}};
    std::uint64_t generation_ = 0;
};

} // namespace penumbra::shadows
