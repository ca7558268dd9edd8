// m * vec4(p, 1) as an explicit chain of fused multiply-adds. Left to themselves the two shader paths
// (SPIR-V -> NIR for Vulkan, SPIR-V -> SPIRV-Cross GLSL -> NIR for GL) contract and round the product
// differently, an ulp that moves vertices by a subpixel step and shadow lookups across a texel edge.
vec4 transformPoint(mat4 m, vec3 p)
{
    precise vec4 result = fma(m[0], vec4(p.x), fma(m[1], vec4(p.y), fma(m[2], vec4(p.z), m[3])));
    return result;
}
