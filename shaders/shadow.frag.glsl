#version 330 core
// Depth only: the depth buffer is the shadow map.
void main() {}
