#pragma once
// The command line's value specifications that are not lights (LightOption.hpp): --size and --camera's
// look-at form. Parsers return nullopt for text that does not follow the syntax or is out of range.
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace penumbra::apps {

inline constexpr std::uint32_t kMaxSize = 8192;

struct Size {
    std::uint32_t width, height;
};

// "WIDTHxHEIGHT", each 1 to kMaxSize.
std::optional<Size> parseSize(const std::string& text);

struct LookAt {
    glm::vec3 position, target;
};

// "px,py,pz:tx,ty,tz": finite, the position not at the target.
std::optional<LookAt> parseLookAt(const std::string& text);

} // namespace penumbra::apps
