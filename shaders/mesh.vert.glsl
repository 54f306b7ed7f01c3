#version 330 core
// Flat-shaded scene faces: one normal and color per face, repeated on its triangles.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProj;

out vec3 vNormal;
out vec3 vColor;
out vec3 vWorld;

void main() {
  vNormal = aNormal;
  vColor = aColor;
  vWorld = aPosition;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
