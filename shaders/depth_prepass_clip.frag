#version 450
// The depth prepass of clip materials (prepass_coverage.glsl).

#include "lit.glsl"
#include "material.glsl"
#include "prepass_coverage.glsl"

void main()
{
    discardClipHoles();
}
