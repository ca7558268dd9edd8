#version 450
// Solid casters write depth only; no discard keeps early depth testing on.

void main()
{
}
