#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

namespace penumbra::render {

// FNV-1a (Fowler, Noll and Vo) over the bytes of plain values: the keys of static shadow maps, which must change when
// what a map was drawn from changes. Floats hash by their bits, so the same planning gives the same key in every
// process and configuration.
class ContentHash {
public:
    template <typename T>
    ContentHash& add(const T& value)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        return addBytes(std::span<const unsigned char>(bytes, sizeof(T)));
    }

    ContentHash& addBytes(std::span<const unsigned char> bytes)
    {
        for (const unsigned char b : bytes)
            hash_ = (hash_ ^ b) * 1099511628211ull;
        return *this;
    }

    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

} // namespace penumbra::render
