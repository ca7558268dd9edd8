#version 450
// Dear ImGui's vertices (apps/viewer/ImGuiRenderer): positions in window pixels, rows counted
// from the top as RHI viewports do, uv into the bound texture, straight-alpha colour.

layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;

// The uniform block ImGuiFrame (`frame`: pixelToNdc), generated from apps/viewer/ImGuiRenderer's ImGuiFrameUniforms.
#include "imgui_blocks.glsl"

layout(location = 0) out vec2 vUv;
layout(location = 1) out vec4 vColor;

void main()
{
    vUv = inUv;
    vColor = inColor;
    gl_Position = vec4(inPosition * frame.pixelToNdc.xy + frame.pixelToNdc.zw, 0.0, 1.0);
}
