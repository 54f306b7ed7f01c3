#version 330 core
// Sun plus sky lighting for flat faces (Z up), in linear space, then gamma 2.2.
in vec3 vNormal;
in vec3 vColor;
in vec3 vWorld;

uniform vec3 uSunDir;     // towards the sun, normalised
uniform vec3 uEye;
uniform float uTint;      // > 0 highlights the selected object
uniform vec3 uTintColor;

out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormal);
  // Faces seen from behind (open shells while modelling) are lit like their front.
  if (dot(n, uEye - vWorld) < 0.0) n = -n;
  float sun = max(dot(n, uSunDir), 0.0);
  float sky = 0.5 + 0.5 * n.z;
  vec3 light = vec3(1.0, 0.97, 0.9) * sun * 0.75 + mix(vec3(0.28, 0.26, 0.24), vec3(0.42, 0.46, 0.52), sky);
  vec3 c = vColor * light;
  c = mix(c, uTintColor, uTint);
  fragColor = vec4(pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
