// Uniform blocks of the lit pass (penumbra::render::LitFrameUniforms, LitObjectUniforms).

layout(std140, binding = 0) uniform Frame {
    mat4 viewProjection;
    vec4 cameraPosition;     // xyz
    vec4 cameraForward;      // xyz, unit: view depth is the distance along it
    vec4 lightColor[8];      // linear rgb x intensity
    vec4 lightDirection[8];  // xyz from the light into the scene, w = shadow slot or -1
    vec4 ambient;            // linear rgb
    ivec4 config;            // directional light count, view (penumbra::render::LitView), local light count, the
                             // visibility view's light (directional lights first, then spot and point lights)
    vec4 localPosition[16];  // xyz, w = 1 / range^2
    vec4 localColor[16];     // linear rgb x intensity, w = 1 for a point light, 0 for a spot light
    vec4 localAxis[16];      // spot cone axis (unit, away from the light)
    vec4 localShadow[16];    // spot angle scale and offset, first shadow tile or -1, shadow strength
} frame;

layout(std140, binding = 1) uniform Object {
    mat4 model;
    mat4 normalMatrix;       // inverse transpose of the model matrix
    vec4 baseColor;          // linear rgb, alpha
    vec4 surface;            // metallic, roughness, alpha cutoff, caster mode (material.glsl)
    ivec4 flags;             // receives shadows, has a base colour texture
} object;

layout(binding = 7) uniform sampler2D baseColorMap; // sRGB-encoded; a white texel for untextured materials

