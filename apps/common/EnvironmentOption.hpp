#pragma once

#include "penumbra/render/Environment.hpp"

#include <optional>
#include <string>

namespace penumbra::apps {

// --environment and the settings' "environment.source": a Radiance .hdr or an .exr file (equirectangular, linear),
// "default" (render::studioEnvironment), "none" (the ambient light instead) or "auto": the default environment for a
// glTF file, which carries none of its own, unless an ambient light is given (--ambient, the settings' "ambient"),
// and none for the built-in scenes, which are lit by their own lights and ambient light.
inline constexpr const char* kEnvironmentSyntax = "FILE.hdr|FILE.exr|default|none|auto";

// The environment of `source` (kEnvironmentSyntax); `autoStudio`: whether auto means the studio (a glTF file without
// an ambient light given), with its
// intensity and rotation. Files are read once per process and path. Throws rhi::Error naming the file for one that
// cannot be read, `what` (the flag or settings field) for an unknown name, an extension other than .hdr or .exr, or
// intensity or rotation out of range.
render::EnvironmentLight environmentOf(const std::string& source, bool autoStudio, float intensity,
                                       float rotationDegrees, const std::string& what);

} // namespace penumbra::apps
