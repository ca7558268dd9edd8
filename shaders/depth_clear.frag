#version 450
// Clears the viewport's depth to the far plane (with an always-passing depth test): a depth clear of one atlas
// tile, which a pass's clear cannot give (it clears the whole attachment).

void main()
{
    gl_FragDepth = PENUMBRA_FAR_DEPTH;
}
