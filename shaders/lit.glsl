// Uniform blocks of the lit pass (penumbra::render::LitFrameUniforms, LitObjectUniforms).

layout(std140, binding = 0) uniform Frame {
    mat4 viewProjection;
    vec4 cameraPosition;     // xyz
    vec4 cameraForward;      // xyz, unit: view depth is the distance along it
    vec4 lightColor[8];      // linear rgb x intensity
    vec4 lightDirection[8];  // xyz from the light into the scene, w = shadow slot or -1
    vec4 ambient;            // linear rgb
    ivec4 config;            // light count, view (0 lit, 1 cascade colours)
} frame;

layout(std140, binding = 1) uniform Object {
    mat4 model;
    mat4 normalMatrix;       // inverse transpose of the model matrix
    vec4 baseColor;          // linear rgb, alpha
    vec4 surface;            // metallic, roughness, alpha cutoff, caster mode (material.glsl)
    ivec4 flags;             // receives shadows
} object;
