#pragma once

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/scene/Scene.hpp"

#include <optional>
#include <string>
#include <variant>

namespace penumbra::apps {

// A light given on the command line (--light), added to whatever the scene has:
//   sun:dx,dy,dz[:intensity]                               direction from the light into the scene
//   spot:px,py,pz:dx,dy,dz:range:outerDegrees[:intensity]  inner angle 0.7 x outer
//   point:px,py,pz:range[:intensity]
using LightOption = std::variant<scene::DirectionalLight, scene::SpotLight, scene::PointLight>;

inline constexpr const char* kLightSyntax = "sun:dx,dy,dz[:intensity], spot:px,py,pz:dx,dy,dz:range:outerDegrees"
                                            "[:intensity] or point:px,py,pz:range[:intensity]";

// A spot light's outer cone angle is below this many degrees: its shadow's perspective projection needs a cone
// narrower than a half space.
inline constexpr float kMaxSpotOuterDegrees = 90.0f;

// nullopt for text that does not follow the syntax or has a zero direction, a range <= 0, an outer angle outside
// (0, kMaxSpotOuterDegrees) or a negative intensity; then `error`, if given, says which: the value and its allowed
// range ("'spot:0,5,0:0,-1,0:10:120': the outer cone angle 120 degrees is outside (0, 90) ..."), or the syntax.
std::optional<LightOption> parseLightOption(const std::string& text, std::string* error = nullptr);

void addLight(scene::Scene& scene, const LightOption& light);

// --ambient r,g,b:intensity[:gr,gg,gb]: linear colour and intensity, and the ground's colour for a sky/ground
// hemisphere (render::AmbientLight).
inline constexpr const char* kAmbientSyntax = "r,g,b:intensity[:groundR,groundG,groundB]";

// --ambient's parts as the render settings' fields ambient.color, ambient.intensity and ambient.ground, each written
// as a settings file holds it (ground `none` without a third part), for the settings table to read and check.
struct AmbientFields {
    std::string color;
    std::string intensity;
    std::string ground;
};
// nullopt for text of other than two or three parts.
std::optional<AmbientFields> ambientFields(const std::string& text);

} // namespace penumbra::apps
