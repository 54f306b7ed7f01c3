#version 330 core
// Flat-shaded scene faces: one normal and color per face, repeated on its triangles; textured
// faces add their texture coordinates and layer (read only where uTextured is set).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;
layout(location = 3) in vec3 aTexCoord;  // u, v, layer of the built-in textures

uniform mat4 uViewProj;

out vec3 vNormal;
out vec3 vColor;
out vec3 vWorld;
out vec3 vTexCoord;

void main() {
  vNormal = aNormal;
  vColor = aColor;
  vWorld = aPosition;
  vTexCoord = aTexCoord;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
