// m * vec4(p, 1) as an explicit chain of fused multiply-adds. Left to themselves the two shader paths
// (SPIR-V -> NIR for Vulkan, SPIR-V -> SPIRV-Cross GLSL -> NIR for GL) contract and round the product
// differently, an ulp that moves vertices by a subpixel step and shadow lookups across a texel edge.
vec4 transformPoint(mat4 m, vec3 p)
{
    precise vec4 result = fma(m[0], vec4(p.x), fma(m[1], vec4(p.y), fma(m[2], vec4(p.z), m[3])));
    return result;
}

// The camera clip position of a model-space point, through its world position. The depth prepass and the lit
// pass both call this, and transformPoint's precise fused multiply-adds leave the compiler no freedom to round
// either differently, so their depths agree to the bit and the lit pass's equal depth test keeps every pixel the
// prepass wrote. (`invariant gl_Position` would say the same, but Mesa's SPIR-V reader warns about the decoration
// on the gl_PerVertex member glslang puts it on.)
vec4 cameraClipPosition(mat4 viewProjection, mat4 model, vec3 p)
{
    return transformPoint(viewProjection, transformPoint(model, p).xyz);
}
