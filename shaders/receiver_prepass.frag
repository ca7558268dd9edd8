#version 450
// The depth prepass of the screen-space shadow path: besides depth, the screen derivatives of the world position
// that lit.frag takes for its shadows (the geometric normal of the normal offset, the soft filters' receiver plane),
// so that the full-screen collection (screen_space_shadows.frag) evaluates them as the forward path does. Depth
// alone would give them only from neighbouring pixels, which at a silhouette belong to another surface. With contact
// shadows, the view depth they march through too (view_depth.glsl).

#include "lit.glsl"
#include "material.glsl"
#include "receiver_prepass_variant.glsl"
#include "view_depth.glsl"
#if PENUMBRA_RECEIVER_CLIP
#include "prepass_coverage.glsl"
#endif

layout(location = 0) in vec3 vPosition;

layout(location = 0) out vec4 outPositionDx;
layout(location = 1) out vec4 outPositionDy;
#if PENUMBRA_RECEIVER_VIEW_DEPTH
layout(location = 2) out float outViewDepth;
#endif

void main()
{
    // Before any discard: derivatives need the whole quad.
    outPositionDx = vec4(dFdxFine(vPosition), 0.0);
    outPositionDy = vec4(dFdyFine(vPosition), 0.0);
#if PENUMBRA_RECEIVER_VIEW_DEPTH
    outViewDepth = prepassViewDepth(PENUMBRA_RECEIVER_CLIP != 0);
#endif
#if PENUMBRA_RECEIVER_CLIP
    discardClipHoles();
#endif
}
