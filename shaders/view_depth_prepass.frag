#version 450
// The depth prepass that also writes the view depth for contact shadows (view_depth.glsl), opaque or with the clip
// materials' alpha test (prepass_coverage.glsl), negated for those. Cleared to 0: no surface.

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
    outViewDepth = prepassViewDepth(PENUMBRA_VIEW_DEPTH_CLIP != 0);
#if PENUMBRA_VIEW_DEPTH_CLIP
    discardClipHoles();
#endif
}
