#pragma once

#include <cstdint>

// A light's shadow options, the one vocabulary of the scene's lights (scene/Light.hpp), the glTF loader, the shadow
// planners (penumbra::shadows uses these types as its own) and the renderer: no module translates between twins.
namespace penumbra::scene {

// Which list of a scene a light is in: Scene::lights, spotLights or pointLights.
enum class LightKind : std::uint8_t { Directional, Spot, Point };

// A light's shadow filter: a percentage-closer tent N texels wide (2x2 is one bilinear tap, "hard"), a
// fixed-radius Poisson disk, or percentage-closer soft shadows (Fernando 2005, "Percentage-Closer Soft Shadows"):
// a blocker search, a penumbra estimate, then the Poisson disk over that penumbra. The values are the lit
// shader's (generated into shadow_constants.glsl by shadows::filterConstantsGlsl); shadows::shadowFilters() holds
// their names and sizes.
enum class ShadowFilter { PCF2x2, PCF3x3, PCF5x5, PCF7x7, Poisson, PCSS };
inline constexpr int kShadowFilterCount = 6;

// Where a light's normal bias is applied: the receiver's lookup moves towards the light (Castano 2013, "Shadow
// Mapping Summary - Part 1"), or the caster's vertices move away from it by the same offset in the shadow pass
// (Unity's UnityClipSpaceShadowCasterPos; Catlike Coding, "Rendering 7: Shadows", section 2.1). The caster side
// keeps the lit pass's lookups where the surface is, but thins casters: thin ones can get holes.
enum class NormalBiasSide : std::uint8_t { Receiver, Caster };

// When a light's static shadow map, the depth of its static casters alone, is drawn (Unity HDRP's shadow update
// modes "Every Frame", "On Enable" and "On Demand"; Godot's shadow atlas re-renders a light only when it changes).
// A light without a mode of its own (std::nullopt) follows the shadow settings' static.update.
enum class StaticShadowUpdate {
    EveryFrame, // no static maps: every caster is drawn into the realtime atlases every frame
    OnChange, // drawn once, then again only when a static caster, the light or its settings change
    OnDemand, // drawn once, then again only when the application asks (SceneRenderer::requestStaticShadowUpdate)
};

// The shadow options a light starts with, for scene lights, the glTF loader and the shadow planners' inputs alike.
struct LightShadowDefaults {
    static constexpr float slopeScaleBias = 1.0f; // the RHI's depth-bias slope factor for the light's casters
    static constexpr float normalBias = 1.0f; // in filter-sized texel diagonals
    static constexpr float nearPlaneOffset = 0.2f; // world units a directional shadow's near plane is pulled back
    // Source sizes: the sun's angular diameter (about 0.53 degrees) and a 5 cm bulb's radius (world units).
    static constexpr float angularDiameter = 0.53f;
    static constexpr float sourceRadius = 0.05f;
};

} // namespace penumbra::scene
