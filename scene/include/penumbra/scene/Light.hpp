#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra::scene {

// Where a light's normal bias moves things (shadows::NormalBiasSide): the receivers' shadow lookups towards the
// light, or the casters' vertices away from it in the shadow pass.
enum class NormalBiasSide : std::uint8_t { Receiver, Caster };

// "receiver", "caster": the names on the command line and in the viewer.
std::string_view normalBiasSideName(NormalBiasSide side);
std::optional<NormalBiasSide> parseNormalBiasSide(std::string_view name);
// When a light's static shadow map (penumbra::shadows::StaticShadowUpdate) is drawn: as the shadow settings'
// static.update says, or the light's own mode. The names are the settings JSON's: "settings", "everyFrame",
// "onChange", "onDemand".
enum class ShadowUpdate : std::uint8_t { Settings, EveryFrame, OnChange, OnDemand };
std::string_view shadowUpdateName(ShadowUpdate update);
std::optional<ShadowUpdate> parseShadowUpdate(std::string_view name);
// "settings, everyFrame, onChange, onDemand": for messages.
inline constexpr const char* kShadowUpdateNames = "settings, everyFrame, onChange, onDemand";

// A light's own shadow filter: a penumbra::shadows::ShadowFilter value, or kAtlasShadowFilter for the shadow
// settings' (the atlas's) filter. The renderer checks the value.
inline constexpr std::int32_t kAtlasShadowFilter = -1;

// Default source sizes: the sun's angular diameter (about 0.53 degrees) and a 5 cm bulb.
inline constexpr float kDefaultAngularDiameter = 0.53f;
inline constexpr float kDefaultSourceRadius = 0.05f;
// Largest angular diameter a directional light may have, degrees (a soft-shadow filter's reach ends far earlier).
inline constexpr float kMaxAngularDiameter = 30.0f;

// A light infinitely far away (a sun): its direction, colour, intensity and shadow options.
struct DirectionalLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, from the light INTO the scene; surfaces are lit from -direction
    float shadowStrength = 1.0f; // 0: shadows ignored, 1: fully dark
    float slopeScaleBias = 1.0f; // the RHI's depth-bias slope factor for this light's casters
    float normalBias = 1.0f; // receiver offset along its normal, in units of the cascade's filter-sized texel diagonal
    float nearPlaneOffset = 0.2f; // pulls the shadow projection's near plane back, in world units
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float angularDiameter = kDefaultAngularDiameter; // source size, degrees, 0..kMaxAngularDiameter (soft shadows)
    std::int32_t shadowFilter = kAtlasShadowFilter;
    ShadowUpdate shadowUpdate = ShadowUpdate::Settings;
};

// A cone light. Its light falls off with distance (zero at range) and between the inner and
// outer cone angles; its shadow map is a perspective projection of the outer cone.
struct SpotLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, the cone's axis pointing away from the light
    float range = 10.0f; // > 0, world units
    float innerAngle = 0.4f; // half-angle of full intensity, radians, 0 <= inner < outer
    float outerAngle = 0.6f; // half-angle where the light ends, radians, < pi/2
    float shadowStrength = 1.0f; // 0: shadows ignored, 1: fully dark
    float slopeScaleBias = 1.0f;
    float normalBias = 1.0f; // receiver offset in filter-sized texel diagonals at the receiver's distance
    float shadowNearPlane = 0.0f; // world units, below range; 0: the shadow settings' local.nearPlane x range
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float sourceRadius = kDefaultSourceRadius; // world units, 0..range: a disk facing the receiver (soft shadows)
    std::int32_t shadowFilter = kAtlasShadowFilter;
    ShadowUpdate shadowUpdate = ShadowUpdate::Settings;
};

// An omnidirectional light; its shadow is six cube faces.
struct PointLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 position{0.0f};
    float range = 10.0f; // > 0, world units
    float shadowStrength = 1.0f;
    float slopeScaleBias = 1.0f;
    float normalBias = 1.0f;
    float shadowNearPlane = 0.0f; // world units, below range; 0: the shadow settings' local.nearPlane x range
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float sourceRadius = kDefaultSourceRadius; // world units, 0..range: a sphere (soft shadows)
    std::int32_t shadowFilter = kAtlasShadowFilter;
    ShadowUpdate shadowUpdate = ShadowUpdate::Settings;
};

// A light of a scene: its kind and its index into Scene::lights, spotLights or pointLights.
enum class LightKind : std::uint8_t { Directional, Spot, Point };
// Names one light of a scene: its kind and its index in that kind's list.
struct LightRef {
    LightKind kind = LightKind::Directional;
    std::uint32_t index = 0;
};

// "directional light", "spot light" or "point light".
const char* lightKindName(LightKind kind);

// Unit light direction for a light pitched `pitch` radians below the horizon and turned
// `yaw` radians about +y, measured from +z towards +x (yaw 0 shines towards +z).
// Pitch turns about +x first and yaw about +y after it, so yaw never tilts the light: the
// elevation stays `pitch` whatever the yaw.
glm::vec3 lightDirection(float pitch, float yaw);

} // namespace penumbra::scene
