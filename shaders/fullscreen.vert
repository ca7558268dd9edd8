#version 450
// One triangle covering the target, counter-clockwise in NDC; no vertex buffer.
// vUv follows the convention's clip-to-texture mapping, so v = 0 is the top row.

layout(location = 0) out vec2 vNdc;
layout(location = 1) out vec2 vUv;

void main()
{
    const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    vNdc = corners[gl_VertexIndex];
    vUv = (PENUMBRA_CLIP_TO_TEXTURE * vec4(vNdc, 0.0, 1.0)).xy;
    gl_Position = vec4(vNdc, 0.0, 1.0);
}
