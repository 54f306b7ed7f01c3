#version 330 core
in vec4 vColor;
in vec3 vWorld;

uniform vec3 uFadeCenter;
uniform float uFadeRadius;  // 0: no fading (edges, overlays); > 0: the grid fades out

out vec4 fragColor;

void main() {
  float a = vColor.a;
  if (uFadeRadius > 0.0) a *= clamp(1.0 - distance(vWorld.xy, uFadeCenter.xy) / uFadeRadius, 0.0, 1.0);
  fragColor = vec4(vColor.rgb, a);
}
