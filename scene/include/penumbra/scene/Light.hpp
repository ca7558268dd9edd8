#pragma once

#include "penumbra/scene/LightShadowOptions.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra::scene {

// "receiver", "caster": the names on the command line and in the viewer.
std::string_view normalBiasSideName(NormalBiasSide side);
std::optional<NormalBiasSide> parseNormalBiasSide(std::string_view name);
// A light's own static shadow map mode, or std::nullopt to follow the shadow settings' static.update.
using LightShadowUpdate = std::optional<StaticShadowUpdate>;
// The mode named `name` in glTF extras or on the command line ("settings" for nullopt, "everyFrame", "onChange",
// "onDemand"), or nullopt when no mode has that name.
std::optional<LightShadowUpdate> parseLightShadowUpdate(std::string_view name);
// "settings, everyFrame, onChange, onDemand": for messages.
inline constexpr const char* kLightShadowUpdateNames = "settings, everyFrame, onChange, onDemand";

// Largest angular diameter a directional light may have, degrees (a soft-shadow filter's reach ends far earlier).
inline constexpr float kMaxAngularDiameter = 30.0f;
// The range of a spot or point light's own shadowResolution, texels per side (the local atlas's tile sizes).
inline constexpr float kMinShadowResolution = 16.0f;
inline constexpr float kMaxShadowResolution = 8192.0f;

// A light infinitely far away (a sun): its direction, colour, intensity and shadow options.
struct DirectionalLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, from the light INTO the scene; surfaces are lit from -direction
    float shadowStrength = 1.0f; // 0: shadows ignored, 1: fully dark
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias; // the RHI's depth-bias slope factor for the casters
    float normalBias =
        LightShadowDefaults::normalBias; // along the normal, in the cascade's filter-sized texel diagonals
    float nearPlaneOffset = LightShadowDefaults::nearPlaneOffset; // pulls the shadow near plane back, world units
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float angularDiameter =
        LightShadowDefaults::angularDiameter; // source size, degrees, 0..kMaxAngularDiameter (soft shadows)
    std::optional<ShadowFilter> shadowFilter; // nullopt: the shadow settings' (the atlas's) filter
    LightShadowUpdate shadowUpdate;
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
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias;
    float normalBias = LightShadowDefaults::normalBias; // in filter-sized texel diagonals at the receiver's distance
    float shadowNearPlane = 0.0f; // world units, below range; 0: the shadow settings' local.nearPlane x range
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float sourceRadius =
        LightShadowDefaults::sourceRadius; // world units, 0..range: a disk facing the receiver (soft shadows)
    std::optional<ShadowFilter> shadowFilter; // nullopt: the shadow settings' (the atlas's) filter
    LightShadowUpdate shadowUpdate;
    // Texels per side its shadow tile asks for when its reach fills the screen (scaled down by its importance on
    // screen); nullopt: the shadow settings' local.tileResolution. kMinShadowResolution..kMaxShadowResolution.
    std::optional<float> shadowResolution;
};

// An omnidirectional light; its shadow is six cube faces.
struct PointLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 position{0.0f};
    float range = 10.0f; // > 0, world units
    float shadowStrength = 1.0f;
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias;
    float normalBias = LightShadowDefaults::normalBias;
    float shadowNearPlane = 0.0f; // world units, below range; 0: the shadow settings' local.nearPlane x range
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    float sourceRadius = LightShadowDefaults::sourceRadius; // world units, 0..range: a sphere (soft shadows)
    std::optional<ShadowFilter> shadowFilter; // nullopt: the shadow settings' (the atlas's) filter
    LightShadowUpdate shadowUpdate;
    // Texels per side its shadow tile asks for when its reach fills the screen (scaled down by its importance on
    // screen); nullopt: the shadow settings' local.tileResolution. kMinShadowResolution..kMaxShadowResolution.
    std::optional<float> shadowResolution;
};

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
