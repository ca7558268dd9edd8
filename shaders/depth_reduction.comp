#version 450
// The nearest and farthest window depth of the pixels the depth prepass drew (render/src/passes/DepthReduction.hpp):
// a workgroup reduces its 16 x 16 pixels in shared memory, then one invocation merges them into the buffer. The
// depths are in [0, 1], whose float bits order as unsigned integers do, so the atomics compare them as uints
// (Lauritzen, Salvi and Lefohn, "Sample Distribution Shadow Maps", I3D 2011, section 4: the min/max reduction).
#include "constants.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D depth;
layout(std430, binding = 1) buffer DepthBounds
{
    uint nearest;
    uint farthest;
}
bounds;

shared uint groupNearest;
shared uint groupFarthest;

void main()
{
    if (gl_LocalInvocationIndex == 0u) {
        groupNearest = 0xffffffffu;
        groupFarthest = 0u;
    }
    barrier();
    const ivec2 size = textureSize(depth, 0);
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(pixel, size))) {
        const float d = texelFetch(depth, pixel, 0).r;
        // The clear value is the background: nothing drawn there.
        if (d != float(PENUMBRA_CLEAR_DEPTH)) {
            const uint bits = floatBitsToUint(d);
            atomicMin(groupNearest, bits);
            atomicMax(groupFarthest, bits);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupNearest <= groupFarthest) {
        atomicMin(bounds.nearest, groupNearest);
        atomicMax(bounds.farthest, groupFarthest);
    }
}
