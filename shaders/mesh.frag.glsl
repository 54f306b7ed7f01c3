#version 330 core
// Sun plus sky lighting for flat faces (Z up), in linear space, then gamma 2.2. With shadows on,
// the sun's share is scaled by how much of a 3 × 3 block of shadow-map taps sees the sun (each
// tap a hardware 2 × 2 depth comparison); the sky's share never changes. Textured faces take
// their albedo from the texel instead of vColor, read as the material colours are (linear).
in vec3 vNormal;
in vec3 vColor;
in vec3 vWorld;
in vec3 vTexCoord;

uniform vec3 uSunDir;     // towards the sun, normalised
uniform vec3 uEye;
uniform float uTint;      // > 0 highlights the selected object
uniform vec3 uTintColor;
uniform int uShadows;     // 1: sample uShadowMap
uniform mat4 uLightViewProj;
uniform sampler2DShadow uShadowMap;
uniform float uShadowTexel;  // 1 / the map's size
uniform int uTextured;       // 1: the albedo is uTextures at vTexCoord
uniform sampler2DArray uTextures;

out vec4 fragColor;

float sunVisible(vec3 n) {
  vec4 p = uLightViewProj * vec4(vWorld, 1.0);
  vec3 q = p.xyz / p.w * 0.5 + 0.5;
  if (q.x < 0.0 || q.x > 1.0 || q.y < 0.0 || q.y > 1.0) return 1.0;  // outside the map: nothing casts there
  // Faces turned from the sun are in their own shadow; a small slope bias against acne.
  float bias = uShadowTexel * (1.0 + 2.0 * (1.0 - max(dot(n, uSunDir), 0.0)));
  float seen = 0.0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) seen += texture(uShadowMap, vec3(q.xy + vec2(i, j) * uShadowTexel, q.z - bias));
  return seen / 9.0;
}

void main() {
  vec3 n = normalize(vNormal);
  // Faces seen from behind (open shells while modelling) are lit like their front.
  if (dot(n, uEye - vWorld) < 0.0) n = -n;
  float sun = max(dot(n, uSunDir), 0.0);
  if (uShadows != 0 && sun > 0.0) sun *= sunVisible(n);
  float sky = 0.5 + 0.5 * n.z;
  vec3 light = vec3(1.0, 0.97, 0.9) * sun * 0.75 + mix(vec3(0.28, 0.26, 0.24), vec3(0.42, 0.46, 0.52), sky);
  vec3 albedo = uTextured != 0 ? texture(uTextures, vTexCoord).rgb : vColor;
  vec3 c = albedo * light;
  c = mix(c, uTintColor, uTint);
  fragColor = vec4(pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
