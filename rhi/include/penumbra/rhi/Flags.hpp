#pragma once

#include <type_traits>

namespace penumbra::rhi {

// Opt-in bitwise operators for flag enums: declare `constexpr bool enableFlags(E) { return true; }`.
template <typename E>
concept FlagEnum = std::is_enum_v<E> && requires(E e)
{
    enableFlags(e);
};

template <FlagEnum E>
constexpr E operator|(E a, E b)
{
    using U = std::underlying_type_t<E>;
    return static_cast<E>(static_cast<U>(a) | static_cast<U>(b));
}

template <FlagEnum E>
constexpr E operator&(E a, E b)
{
    using U = std::underlying_type_t<E>;
    return static_cast<E>(static_cast<U>(a) & static_cast<U>(b));
}

template <FlagEnum E>
constexpr E& operator|=(E& a, E b)
{
    return a = a | b;
}

// Whether every flag of `flags` is in `set`.
template <FlagEnum E>
constexpr bool hasAll(E set, E flags)
{
    using U = std::underlying_type_t<E>;
    return (static_cast<U>(set) & static_cast<U>(flags)) == static_cast<U>(flags);
}

template <FlagEnum E>
constexpr bool hasFlag(E set, E flag)
{
    using U = std::underlying_type_t<E>;
    return (static_cast<U>(set) & static_cast<U>(flag)) != 0;
}

} // namespace penumbra::rhi
