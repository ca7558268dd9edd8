#pragma once

#include "penumbra/shadows/ShadowCamera.hpp"

#include <glm/vec3.hpp>

#include <optional>

namespace penumbra::shadows {

// How large a shadow tile a spot or point light asks for: its own resolution (or the default) scaled by its importance
// on screen, within [floorSize, maxSize]. Unity HDRP's "dynamic rescale" does the same with the screen size of the
// light's range (HDRP manual, "Shadows in HDRP", Dynamic Rescale); the result feeds ShadowTileRequest.
struct ShadowResolutionLimits {
    float floorSize = 64.0f; // texels on a side: the least a light asks for, however small or far
    float maxSize = 1024.0f; // the most, whatever its own setting
    float defaultSize = 512.0f; // what a light without its own resolution asks for when it fills the screen
};

// What decides a spot or point light's shadow resolution: where it is, how far it reaches, how bright it is.
struct LocalLightImportance {
    glm::vec3 position{0.0f};
    float range = 10.0f; // > 0: the sphere the light reaches (a spot light's cone lies within it)
    float relativeIntensity = 1.0f; // the light's intensity over the frame's brightest local light's, 0..1
    std::optional<float> shadowResolution; // the light's own setting (texels); nullopt: the default
};

// The shadow tile size a light asks for, and its priority when space runs out.
struct ShadowResolutionRequest {
    float size = 0.0f; // texels on a side, floorSize..maxSize
    float priority = 0.0f; // 0..1: screen importance, for the packer's degradation order
};

// The height of a sphere's projection as a fraction of the screen's (tan of its angular radius over tan of half the
// vertical field of view: exact for a sphere on the view axis, its width off the axis stretches): 0 when the sphere
// lies wholly outside the view frustum, 1 when it covers the screen's height or holds the camera.
float projectedSphereHeight(const ShadowCamera& camera, glm::vec3 centre, float radius);

// The light's importance, 0..1: its range's projected height times the square root of its relative intensity
// (perceived brightness grows about as the square root of a small source's luminance: Stevens, "On the
// psychophysical law", Psychological Review 64(3), 1957). Non-decreasing as the light nears the camera or grows
// brighter.
float localShadowPriority(const ShadowCamera& camera, const LocalLightImportance& light);

// The light's own resolution (or limits.defaultSize) times its priority, clamped to [floorSize, maxSize]: an
// off-screen or tiny light asks for the floor. Throws rhi::Error for limits that are not 0 < floorSize <= maxSize,
// or a range or own resolution that is not a positive finite number.
ShadowResolutionRequest localShadowRequest(const ShadowCamera& camera, const LocalLightImportance& light,
                                           const ShadowResolutionLimits& limits = {});

} // namespace penumbra::shadows
