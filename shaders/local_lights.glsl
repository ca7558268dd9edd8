// The lit pass's spot and point lights and their clustered lists (penumbra::render::LocalLightTextures), read with
// texelFetch from data textures (the layout is LitUniforms.hpp's, generated into lit_constants.glsl): a fragment
// finds its cluster as penumbra::shadows::clusterIndex does (Olsson, Billeter and Assarsson, "Clustered Deferred and
// Forward Shading", HPG 2012) and walks that cluster's lights only. Needs lit.glsl first.

layout(binding = PENUMBRA_BINDING_LOCAL_LIGHTS) uniform sampler2D localLightData;    // RGBA32F
layout(binding = PENUMBRA_BINDING_LIGHT_CLUSTERS) uniform sampler2D lightClusterData; // RGBA32F: first entry, count
layout(binding = PENUMBRA_BINDING_LIGHT_INDICES) uniform sampler2D lightIndexData;    // R32F: local light index

ivec2 litDataTexel(int t) { return ivec2(t & (PENUMBRA_LIT_DATA_WIDTH - 1), t >> PENUMBRA_LIT_DATA_WIDTH_LOG2); }

// Texel `texel` of local light `light`, for the accessors of its fields that follow (LitUniforms.hpp's
// LocalLightRecord: localLightPosition(light), localLightColor(light)...).
vec4 localLightTexel(int light, int texel)
{
    return texelFetch(localLightData, litDataTexel(light * PENUMBRA_LOCAL_LIGHT_TEXELS + texel), 0);
}
#include "local_light_record.glsl"

// The list of the cluster holding world-space `position`: its first entry in the index texture and its length.
ivec2 clusterLightList(vec3 position)
{
    const vec3 d = position - frame.cameraPosition.xyz;
    const float depth = max(dot(d, frame.cameraForward.xyz), frame.clusterNear);
    const vec2 ndc = vec2(dot(d, frame.cameraRight), dot(d, frame.cameraUp)) /
                     (vec2(frame.tanHalfFovX, frame.tanHalfFovY) * depth);
    const int x = clamp(int(floor((ndc.x + 1.0) * 0.5 * float(PENUMBRA_CLUSTER_TILES_X))), 0,
                        PENUMBRA_CLUSTER_TILES_X - 1);
    const int y = clamp(int(floor((1.0 - ndc.y) * 0.5 * float(PENUMBRA_CLUSTER_TILES_Y))), 0,
                        PENUMBRA_CLUSTER_TILES_Y - 1);
    const int slice = clamp(int(floor(log(depth) * frame.clusterSliceScale + frame.clusterSliceBias)), 0,
                            PENUMBRA_CLUSTER_SLICES - 1);
    const int cluster = x + PENUMBRA_CLUSTER_TILES_X * (y + PENUMBRA_CLUSTER_TILES_Y * slice);
    return ivec2(texelFetch(lightClusterData, litDataTexel(cluster), 0).xy);
}

// Entry `entry` of the index texture: a local light.
int clusterLight(int entry) { return int(texelFetch(lightIndexData, litDataTexel(entry), 0).r); }
