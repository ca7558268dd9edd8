#version 450
// One level of an environment's specular chain (render/src/EnvironmentMaps.cpp), an equirectangular RGBA16F texture
// whose level m holds the environment convolved with the GGX lobe of perceptual roughness m / (levels - 1), with
// n = v = r (Karis 2013, "Real Shading in Unreal Engine 4", section "Image Based Lighting": the split sum's first
// sum). Level 0 is the source itself. Samples read the source's box-filtered mips at the level whose texels match the
// sample's share of the lobe (Colbert and Krivanek 2007, "GPU-Based Importance Sampling", GPU Gems 3 chapter 20).

#include "environment.glsl"
#include "constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source; // RGBA16F with PENUMBRA_ENVIRONMENT_LEVELS levels
layout(binding = 1, rgba16f) uniform writeonly image2D level;

void main()
{
    const ivec2 size = imageSize(level);
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, size)))
        return;
    const ivec2 sourceSize = textureSize(source, 0);
    const int index = findMSB(sourceSize.x / size.x);
    if (index == 0) {
        imageStore(level, texel, texelFetch(source, texel, 0));
        return;
    }
    const float roughness = float(index) / float(PENUMBRA_ENVIRONMENT_LEVELS - 1);
    const float a = roughness * roughness;
    const float a2 = a * a;
    const vec3 n = equirectDirection((vec2(texel) + 0.5) / vec2(size));
    const vec3 up = abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    const vec3 tangentX = normalize(cross(up, n));
    const vec3 tangentY = cross(n, tangentX);
    // An equirectangular texel's mean solid angle: 4 pi over (width x height x 2 / pi) texels' worth, 2 pi^2 / (w h).
    const float texelSolidAngle = 2.0 * ENVIRONMENT_PI * ENVIRONMENT_PI / float(sourceSize.x * sourceSize.y);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint k = 0u; k < uint(PENUMBRA_ENVIRONMENT_SAMPLES); ++k) {
        const vec2 xi = hammersley(k, uint(PENUMBRA_ENVIRONMENT_SAMPLES));
        const float phi = 2.0 * ENVIRONMENT_PI * xi.x;
        const float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (a2 - 1.0) * xi.y));
        const float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
        const vec3 h = tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) + n * cosTheta;
        const vec3 l = 2.0 * dot(n, h) * h - n;
        const float nl = dot(n, l);
        if (nl > 0.0) {
            // With n = v the pdf of l is D(h) / 4.
            const float d = cosTheta * cosTheta * (a2 - 1.0) + 1.0;
            const float pdf = a2 / (ENVIRONMENT_PI * d * d) / 4.0;
            const float sampleSolidAngle = 1.0 / (float(PENUMBRA_ENVIRONMENT_SAMPLES) * pdf);
            const float lod = max(0.5 * log2(sampleSolidAngle / texelSolidAngle) + 1.0, 0.0);
            sum += textureLod(source, equirectUv(l), lod).rgb * nl;
            weight += nl;
        }
    }
    imageStore(level, texel, vec4(sum / max(weight, 1e-4), 1.0));
}
