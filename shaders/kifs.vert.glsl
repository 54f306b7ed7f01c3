#version 330 core
// Where kifs.frag.glsl runs (render/kifs_pass.cpp): the back faces of a box that holds the
// bounds grown by at least two pixels on screen, so only pixels whose rays can meet the building
// are shaded; llvmpipe runs a masked-off branch of a fragment shader anyway, so pixels outside
// the building's box would otherwise pay for the march and the shading (docs/kifs.md, "Speed").
// With uFullScreen (the eye inside or near that box) one triangle covering the viewport.
uniform mat4 uViewProj;
uniform vec3 uCoverLo;
uniform vec3 uCoverHi;
uniform int uFullScreen;

// Corners x + 2y + 4z; triangles counter-clockwise seen from outside the box.
const int kCorner[36] = int[36](0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3,
                                1, 4, 5, 7, 4, 7, 6);

void main() {
  if (uFullScreen != 0) {
    gl_Position = vec4((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0, 0.0, 1.0);
    return;
  }
  int c = kCorner[gl_VertexID];
  vec3 p = mix(uCoverLo, uCoverHi, vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)));
  gl_Position = uViewProj * vec4(p, 1.0);
}
