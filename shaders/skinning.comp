#version 450
// GPU skinning (penumbra::render::GpuSkinning): one deformed mesh's vertices at the frame's pose, written into the
// vertex buffer that every pass draws it from. Morph targets first (glTF 2.0 section 3.7.2.2), then linear blend
// skinning (section 3.7.3): the math of scene/src/Skinning.cpp, which stays the reference (the ground truth's ray
// caster skins on the CPU).

#include "constants.glsl"

layout(local_size_x = 64) in;

// scene::Vertex as floats, and where its position, normal and tangent start (from its C++ declaration).
const uint kVertexFloats = PENUMBRA_VERTEX_FLOATS;
const uint kVertexPosition = PENUMBRA_VERTEX_POSITION;
const uint kVertexNormal = PENUMBRA_VERTEX_NORMAL;
const uint kVertexTangent = PENUMBRA_VERTEX_TANGENT;
// MorphTarget offsets as floats per target and vertex: position, normal, tangent xyz (0 where the target has none).
const uint kTargetFloats = PENUMBRA_TARGET_FLOATS;
const uint kTargetPosition = PENUMBRA_TARGET_POSITION;
const uint kTargetNormal = PENUMBRA_TARGET_NORMAL;
const uint kTargetTangent = PENUMBRA_TARGET_TANGENT;
const uint kSkinned = PENUMBRA_DEFORM_SKINNED; // Deform.flags: the deformer has a skin
// Deform.flags: each triangle's vertices get its face normal (a file without normals)
const uint kFlatNormals = PENUMBRA_DEFORM_FLAT_NORMALS;

// The storage blocks, generated from their C++ declarations (render/src/skinning/GpuSkinning.cpp): `deform` (the
// header and targetCount morph weights), and as globals rest[], influences[], targets[], joints[] and posed[].
#include "skinning_blocks.glsl"

vec3 restVec3(uint v, uint at)
{
    const uint base = v * kVertexFloats + at;
    return vec3(rest[base], rest[base + 1], rest[base + 2]);
}

vec3 targetVec3(uint t, uint v, uint at)
{
    const uint base = (t * deform.vertexCount + v) * kTargetFloats + at;
    return vec3(targets[base], targets[base + 1], targets[base + 2]);
}

vec3 normalizedOr(vec3 v, vec3 fallback)
{
    const float l = length(v);
    return l > 0.0 ? v / l : fallback;
}

// Section 3.7.3.3: sum over the vertex's influences of weight * joint matrix. Here and below `precise` with explicit
// fused multiply-adds leaves neither shader path (SPIR-V for Vulkan, SPIRV-Cross GLSL for GL) free to contract and
// round differently, as transform.glsl explains, so both backends pose a vertex to the same bits.
mat4 skinMatrix(uint v)
{
    precise mat4 sum = mat4(0.0);
    for (uint set = 0; set < deform.influenceSets; ++set) {
        const Influence influence = influences[v * deform.influenceSets + set];
        for (int i = 0; i < 4; ++i)
            if (influence.weights[i] != 0.0) {
                const mat4 joint = joints[influence.joints[i]];
                for (int c = 0; c < 4; ++c)
                    sum[c] = fma(vec4(influence.weights[i]), joint[c], sum[c]);
            }
    }
    return sum;
}

// m * p for the linear part of a matrix, as fused multiply-adds.
vec3 linearTimes(mat4 m, vec3 p)
{
    precise vec3 result = fma(m[0].xyz, vec3(p.x), fma(m[1].xyz, vec3(p.y), m[2].xyz * p.z));
    return result;
}

struct Deformed {
    vec3 position;
    vec3 normal;
    vec4 tangent;
};

Deformed deformed(uint v)
{
    precise vec3 position = restVec3(v, kVertexPosition);
    precise vec3 normal = restVec3(v, kVertexNormal);
    precise vec3 tangent = restVec3(v, kVertexTangent);
    const vec3 restNormal = normal;
    const vec3 restTangent = tangent;
    for (uint t = 0; t < deform.targetCount; ++t) {
        const float w = deform.weights[t];
        position = fma(vec3(w), targetVec3(t, v, kTargetPosition), position);
        normal = fma(vec3(w), targetVec3(t, v, kTargetNormal), normal);
        tangent = fma(vec3(w), targetVec3(t, v, kTargetTangent), tangent);
    }
    Deformed d;
    if ((deform.flags & kSkinned) != 0u) {
        const mat4 skin = skinMatrix(v);
        precise vec3 skinned = linearTimes(skin, position) + skin[3].xyz;
        d.position = skinned;
        const mat3 normalMatrix = transpose(inverse(mat3(skin)));
        precise vec3 skinnedNormal = fma(normalMatrix[0], vec3(normal.x),
                                         fma(normalMatrix[1], vec3(normal.y), normalMatrix[2] * normal.z));
        d.normal = normalizedOr(skinnedNormal, normal);
        d.tangent.xyz = normalizedOr(linearTimes(skin, tangent), tangent);
    } else {
        d.position = position;
        d.normal = normalizedOr(normal, restNormal);
        d.tangent.xyz = normalizedOr(tangent, restTangent);
    }
    d.tangent.w = rest[v * kVertexFloats + kVertexTangent + 3u];
    return d;
}

void main()
{
    const uint v = gl_GlobalInvocationID.x;
    if (v >= deform.vertexCount)
        return;
    Deformed d = deformed(v);
    const uint first = v - v % 3u;
    if ((deform.flags & kFlatNormals) != 0u && first + 2u < deform.vertexCount) {
        // The flat-shaded layout: vertices 3t, 3t + 1 and 3t + 2 make triangle t; degenerate ones face +y.
        const vec3 p0 = first == v ? d.position : deformed(first).position;
        const vec3 p1 = first + 1u == v ? d.position : deformed(first + 1u).position;
        const vec3 p2 = first + 2u == v ? d.position : deformed(first + 2u).position;
        d.normal = normalizedOr(cross(p1 - p0, p2 - p0), vec3(0.0, 1.0, 0.0));
    }
    const uint base = v * kVertexFloats;
    for (uint i = 0; i < kVertexFloats; ++i)
        posed[base + i] = rest[base + i];
    for (uint i = 0; i < 3u; ++i) {
        posed[base + kVertexPosition + i] = d.position[i];
        posed[base + kVertexNormal + i] = d.normal[i];
        posed[base + kVertexTangent + i] = d.tangent[i];
    }
}
