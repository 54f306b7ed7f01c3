#version 330 core
// Composites a cached KIFS layer (render/kifs_layer.h): the building ray-marched alone into
// colour and depth textures, possibly at 1/uScale of the viewport while the view moves. Each
// pixel takes its texel (nearest), is dropped where the ray missed, and writes the cached depth
// so the depth test still hides it behind the Scene's nearer objects.
uniform sampler2D uColor;
uniform sampler2D uDepth;
uniform ivec4 uViewport;  // x, y, width, height of the target viewport, in pixels
uniform int uScale;       // viewport pixels per layer texel
out vec4 fragColor;
void main() {
  ivec2 p = (ivec2(gl_FragCoord.xy) - uViewport.xy) / uScale;
  ivec2 size = textureSize(uDepth, 0);
  p = clamp(p, ivec2(0), size - 1);
  float d = texelFetch(uDepth, p, 0).r;
  if (d >= 1.0) discard;
  fragColor = texelFetch(uColor, p, 0);
  gl_FragDepth = d;
}
