#version 450
// The depth prepass that also writes the view depth for contact shadows (view_depth.glsl), opaque or with the clip
// materials' alpha test (prepass_coverage.glsl). Cleared to 0: no surface.

#include "lit.glsl"
#include "material.glsl"
#include "view_depth.glsl"
#include "view_depth_prepass_variant.glsl"
#if PENUMBRA_VIEW_DEPTH_CLIP
#include "prepass_coverage.glsl"
#endif

layout(location = 0) out float outViewDepth;

void main()
{
    outViewDepth = fragmentViewDepth();
#if PENUMBRA_VIEW_DEPTH_CLIP
    discardClipHoles();
#endif
}
