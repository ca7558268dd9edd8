#version 450
// Dear ImGui's vertices (apps/viewer/ImGuiRenderer): positions in window pixels, rows counted
// from the top as RHI viewports do, uv into the bound texture, straight-alpha colour.

#include "constants.glsl"

layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;

// xy: pixels to NDC scale, zw: offset; y is negative because canonical NDC y points up.
layout(std140, binding = PENUMBRA_BINDING_FRAME) uniform ImGuiFrame {
    vec4 pixelToNdc;
} frame;

layout(location = 0) out vec2 vUv;
layout(location = 1) out vec4 vColor;

void main()
{
    vUv = inUv;
    vColor = inColor;
    gl_Position = vec4(inPosition * frame.pixelToNdc.xy + frame.pixelToNdc.zw, 0.0, 1.0);
}
