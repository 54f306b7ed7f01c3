#version 330 core
// KIFS buildings (McGraw, Sec. 3): the twin of src/kifs/distance.cpp and trace.cpp, line for
// line (docs/kifs.md). Drawn over the whole viewport with background.vert.glsl; each pixel
// marches its ray, shades the hit and writes gl_FragDepth, so the building composes with the
// rasterized Scene. Uniforms are written by render/kifs_pass.cpp from one KifsParams.

// Camera and viewport.
uniform mat4 uViewProj;
uniform mat4 uInvViewProj;
uniform vec3 uEye;
uniform int uOrtho;  // an orthographic view: parallel rays from the eye's plane
uniform vec4 uViewport;  // x, y, width, height in window pixels

// Algorithm 1.
uniform int uIterations;
uniform float uScale;
uniform vec3 uCentre;
uniform mat3 uR1;
uniform mat3 uR2;
uniform float uBailout;
uniform float uRho;

// Mass model (Eq. 1-3): half-width, half-depth, height.
uniform vec3 uMass;
uniform float uWing;
uniform float uShell;

#if KIFS_FOOTPRINT == 3
// A mass object's shell: its baked distance (kifs/mass_field.h), samples already lowered to a
// bound, read with texelFetch and interpolated here as the CPU does (never the texture unit's
// filtering, whose weights have only a few bits).
uniform sampler3D uMassField;
uniform vec3 uFieldOrigin;
uniform float uFieldCell;
uniform ivec3 uFieldCount;
uniform vec3 uShellLo;
uniform vec3 uShellHi;
uniform vec3 uFrameOrigin;  // the followed object's frame (MassField::toFrame)
uniform vec2 uFrameAxis;
#if KIFS_WALLS
// Walls facing more than one way (kifs/facings.h): each wall in the frame's plan (a.xy, b.xy)
// and its facing, each facing's axis (cos, sin; MassField::facings).
uniform int uWallCount;
uniform vec4 uWalls[KIFS_MAX_WALLS];
uniform int uWallFacing[KIFS_MAX_WALLS];
uniform int uFacingCount;
uniform vec2 uFacings[KIFS_MAX_FACINGS];
#endif
#endif

// Algorithm 2 and the id transform; Eq. 4 (h, y0, s_y); stretch L_f.
uniform float uPeriod;
uniform vec3 uFoldR;
uniform vec4 uIdTransform;  // a1, a2, b1, b2
uniform vec3 uFloors;
uniform float uStretch;

// Eq. 5-6: s_θ, c_θ, s_r, c_r; z0; the annulus (inner, outer radius).
uniform vec4 uPolar;
uniform float uPolarZ0;
uniform vec2 uRing;

// The building's variant, compiled in (render/kifs_pass.cpp defines KIFS_* before this file):
// llvmpipe runs both sides of every branch, even on a uniform, so what a building does not use
// must not be in its program. R1, R2 = I skip their products (I·p = p exactly); footprint 0 box,
// 1 T, 2 H, 3 a mass object's baked field; ids are cells (a1 or b1 ≠ 0); curvilinear
// coordinates; a closed ring has no seam.
const bool kR1Identity = KIFS_R1_IDENTITY != 0;
const bool kR2Identity = KIFS_R2_IDENTITY != 0;
const int kFootprint = KIFS_FOOTPRINT;
const bool kIdsCut = KIFS_IDS_CUT != 0;
const bool kCurvilinear = KIFS_CURVILINEAR != 0;
const bool kClosedRing = KIFS_CLOSED_RING != 0;

// Tracing.
uniform int uMaxSteps;
uniform float uLipschitz;
uniform float uOverRelax;
uniform float uHitFactor;
uniform float uPixelAngle;
uniform vec3 uBoundsLo;
uniform vec3 uBoundsHi;

// Shading: 0 shaded, 1 facade ids, 2 floors (Fig. 5-6), 3 data for render/kifs_pass: the
// pixel's evaluations 255·(r + 256·g), and at a hit id_x + 4·id_z as 255·b and the storey
// + 128 as 255·a; 4 preview: shaded without the soft shadow and the occlusion (the coarse
// frames of render/kifs_layer).
uniform int uMode;
uniform vec3 uSunDir;

out vec4 fragColor;

const float kInf = 1e30;
const float kMinRadius = 1e-6;      // kifs/tolerances.h
const float kMinHitDistance = 1e-7;

int gEvaluations = 0;  // evaluate() calls of this pixel (mode 3)

struct Sample {
  float bound;
  float surface;
  vec2 ids;
  float floorIndex;
};

float kifs(vec3 p) {
  // Uniforms read once, before the loop: on llvmpipe a product with uR1 inside the loop cost
  // about as much as the rest of the fold (measured; docs/kifs.md, "Speed"). The products are
  // written as GLSL defines R·p, column by column, so the results are the same to the bit.
  float s = uScale, h = 0.5 * uCentre.z * (s - 1.0), bailout = uBailout;
  vec2 c = uCentre.xy;
  vec3 r1x = uR1[0], r1y = uR1[1], r1z = uR1[2], r2x = uR2[0], r2y = uR2[1], r2z = uR2[2];
  int iterations = uIterations;
  float scl = 1.0;
  for (int i = 0; i <= iterations; ++i) {
    if (!kR1Identity) p = r1x * p.x + r1y * p.y + r1z * p.z;
    p = abs(p);
    if (p.x < p.y) p.xy = p.yx;
    if (p.x < p.z) p.xz = p.zx;
    if (p.y < p.z) p.yz = p.zy;
    if (!kR2Identity) p = r2x * p.x + r2y * p.y + r2z * p.z;
    p.x = s * (p.x - c.x) + c.x;
    p.y = s * (p.y - c.y) + c.y;
    p.z = h - abs(s * p.z - h);
    scl *= s;
    if (dot(p, p) > bailout) break;
  }
  return (length(p) - uRho) / scl;
}

float boxDistance(vec3 p, vec3 centre, vec3 halfSize) {
  vec3 q = abs(p - centre) - halfSize;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float massBox(vec3 b, float inset, float cx, float cz, float hx, float hz) {
  float top = uMass.z - inset;
  return boxDistance(b, vec3(cx, 0.5 * top, cz), vec3(hx - inset, 0.5 * top, hz - inset));
}

float massModel(vec3 b, float inset) {
  float hx = uMass.x, hz = uMass.y, w = uWing;
  if (kFootprint == 0) return massBox(b, inset, 0.0, 0.0, hx, hz);
  if (kFootprint == 1) return min(massBox(b, inset, 0.0, hz - w, hx, w), massBox(b, inset, 0.0, 0.0, w, hz));
  return min(min(massBox(b, inset, -(hx - w), 0.0, w, hz), massBox(b, inset, hx - w, 0.0, w, hz)),
             massBox(b, inset, 0.0, 0.0, hx, w));
}

#if KIFS_FOOTPRINT == 3
float fieldAt(ivec3 i) { return texelFetch(uMassField, i, 0).r; }

// MassField::distance.
float massField(vec3 p) {
  vec3 gridHi = uFieldOrigin + uFieldCell * vec3(uFieldCount - 1);
  vec3 q = clamp(p, uFieldOrigin, gridHi);
  vec3 u = (q - uFieldOrigin) / uFieldCell;
  ivec3 i = clamp(ivec3(floor(u)), ivec3(0), uFieldCount - 2);
  vec3 t = clamp(u - vec3(i), 0.0, 1.0);
  float r00 = fieldAt(i), r10 = fieldAt(i + ivec3(0, 1, 0)), r01 = fieldAt(i + ivec3(0, 0, 1)),
        r11 = fieldAt(i + ivec3(0, 1, 1));
  r00 += t.x * (fieldAt(i + ivec3(1, 0, 0)) - r00);
  r10 += t.x * (fieldAt(i + ivec3(1, 1, 0)) - r10);
  r01 += t.x * (fieldAt(i + ivec3(1, 0, 1)) - r01);
  r11 += t.x * (fieldAt(i + ivec3(1, 1, 1)) - r11);
  float a = r00 + t.y * (r10 - r00), b = r01 + t.y * (r11 - r01);
  float inside = a + t.z * (b - a);
  if (q == p) return inside;
  vec3 gap = max(max(uShellLo - p, p - uShellHi), 0.0);
  return max(inside - length(p - q), length(gap));
}

#if KIFS_WALLS
float wallDistance(vec2 p, vec4 w) {
  vec2 ab = w.zw - w.xy, ap = p - w.xy;
  float len2 = dot(ab, ab);
  float t = len2 > 0.0 ? clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return length(ap - t * ab);
}

// MassField::facingAt: (the nearest wall's facing, the next facing, half the first's lead over
// it, half the first's lead over a third).
vec4 facingAt(vec2 p) {
  float nearest[KIFS_MAX_FACINGS];
  for (int f = 0; f < KIFS_MAX_FACINGS; ++f) nearest[f] = kInf;
  for (int i = 0; i < uWallCount; ++i) {
    int f = uWallFacing[i];
    nearest[f] = min(nearest[f], wallDistance(p, uWalls[i]));
  }
  // The three nearest facings, in order (a, b, c; −1: none).
  int a = -1, b = -1, c = -1;
  float da = kInf, db = kInf, dc = kInf;
  for (int f = 0; f < uFacingCount; ++f) {
    float d = nearest[f];
    if (a < 0 || d < da) {
      c = b, dc = db, b = a, db = da, a = f, da = d;
    } else if (b < 0 || d < db) {
      c = b, dc = db, b = f, db = d;
    } else if (c < 0 || d < dc) {
      c = f, dc = d;
    }
  }
  int facing = max(a, 0);
  int other = b < 0 ? facing : b;
  float gap = b < 0 ? kInf : 0.5 * (db - da);
  float beyond = c < 0 ? kInf : 0.5 * (dc - da);
  return vec4(float(facing), float(other), gap, beyond);
}
#endif
#endif

// Algorithm 2 for one coordinate: (fold value, id, gap in fold units).
vec3 facadeFold(float x) {
  float f = abs(2.0 * mod(x, uPeriod) / uPeriod - 1.0);
  float id = 0.0, gap = kInf;
  for (int i = 0; i < 3; ++i) {
    f = abs(f - uFoldR[i]) - uFoldR[i];
    if (f > 0.0) id += 1.0;
    gap = min(gap, abs(f));
    f = abs(f);
  }
  return vec3(f, id, gap);
}

float polarStretch(float r) { return max(max(1.0, uPolar.z), uPolar.x / max(r, kMinRadius)); }

// Algorithm 1 on the folds of mass-model coordinates m (Algorithm 2, Eq. 4): (d_KIFS, the cell
// the bound may step in, the ids), as foldCell in kifs/distance.cpp; withBound false skips the
// neighbouring storey and the id caps, which only the bound uses.
vec4 foldCell(vec3 m, float d0, bool withBound) {
  vec3 fx = facadeFold(m.x), fz = facadeFold(m.z);
  float fh = uFloors.x;
  float my = mod(m.y - uFloors.y, fh);  // Eq. 4
  vec4 a = uIdTransform;
  vec3 q = vec3((a.x * fx.y + a.y) * fx.x + a.z * fx.y + a.w, uFloors.z * my / fh,
                (a.x * fz.y + a.y) * fz.x + a.z * fz.y + a.w);
  float dk = kifs(q) / uStretch;
  bool below = my < 0.5 * fh;
  float gapNear = below ? my : fh - my, gapFar = fh - gapNear;
  float cell = min(dk, gapFar);
  if (withBound && gapNear < cell && d0 < cell) {
    vec3 qn = q;
    qn.y = uFloors.z * (below ? my + fh : my - fh) / fh;
    cell = min(cell, max(gapNear, kifs(qn) / uStretch));
  }
  if (withBound && kIdsCut) cell = min(cell, min(0.5 * fx.z * uPeriod, 0.5 * fz.z * uPeriod));
  return vec4(dk, cell, fx.y, fz.y);
}

#if KIFS_FOOTPRINT == 3 && KIFS_WALLS
// Building coordinates (y up) in a facing's turn of a point d = world − uFrameOrigin.
vec3 facingBuilding(vec3 d, int facing) {
  vec2 t = uFacings[facing];
  return vec3(t.x * d.x + t.y * d.y, d.z, -t.y * d.x + t.x * d.y);
}
#endif

// withBound false: only the estimate (normals, occlusion); o.bound is then not a bound. It
// skips the neighbouring storey's second Algorithm 1, the id caps and the neighbouring facing,
// which only the bound uses.
Sample evaluateFor(vec3 world, bool withBound) {
  ++gEvaluations;
#if KIFS_FOOTPRINT == 3
  vec3 d = world - uFrameOrigin;
  vec3 b = vec3(uFrameAxis.x * d.x + uFrameAxis.y * d.y, d.z, -uFrameAxis.y * d.x + uFrameAxis.x * d.y);
#if KIFS_WALLS
  vec4 at = facingAt(b.xz);
  b = facingBuilding(d, int(at.x));
#endif
#else
  vec3 b = world.xzy;  // building coordinates, y up
#endif
  vec3 m = b;
  float radius = 0.0, ring = -kInf, cut = kInf;
  if (kCurvilinear) {  // Eq. 5-6
    float dx = b.x, dz = b.z - uPolarZ0;
    radius = sqrt(dx * dx + dz * dz);
    m.x = uPolar.x * (atan(dz, dx) + uPolar.y);
    m.z = uPolar.z * (radius + uPolar.w);
    ring = max(max(uRing.x - radius, radius - uRing.y), max(-b.y, b.y - uMass.z));
    if (!kClosedRing) cut = dx < 0.0 ? abs(dz) : radius;
  }
#if KIFS_FOOTPRINT == 3
  float d0 = massField(world), di = d0 + uShell;
#else
  float di = massModel(m, uShell), d0 = massModel(m, 0.0);
#endif
  if (uMode == 5) di = kInf;  // bare: no inner shell (Fig. 3c); less solid, so every bound below still holds
  vec4 own = foldCell(m, d0, withBound);
  Sample o;
  o.ids = own.zw;
  o.floorIndex = floor((m.y - uFloors.y) / uFloors.x);
  float cell = own.y;
#if KIFS_FOOTPRINT == 3 && KIFS_WALLS
  if (withBound && at.z < cell && d0 < cell)
    cell = min(min(cell, max(at.z, foldCell(facingBuilding(d, int(at.y)), d0, true).y)), at.w);
#endif
  float surface = min(di, max(d0, own.x));
  float bound = min(di, max(d0, cell));
  if (!kCurvilinear) {
    o.surface = surface;
    o.bound = bound;
    return o;
  }
  float first = bound / polarStretch(radius);
  float safe = bound > 0.0 ? bound / polarStretch(radius - first) : first;
  o.surface = max(ring, surface / polarStretch(radius));
  o.bound = max(ring, min(safe, cut));
  return o;
}

Sample evaluate(vec3 world) { return evaluateFor(world, true); }
float surfaceAt(vec3 world) { return evaluateFor(world, false).surface; }

bool rayBox(vec3 ro, vec3 rd, out float t0, out float t1) {
  vec3 inv = 1.0 / rd;
  vec3 ta = (uBoundsLo - ro) * inv, tb = (uBoundsHi - ro) * inv;
  vec3 lo = min(ta, tb), hi = max(ta, tb);
  t0 = max(max(lo.x, lo.y), lo.z);
  t1 = min(min(hi.x, hi.y), hi.z);
  return t1 >= max(t0, 0.0);
}

// Sphere tracing with over-relaxation and fallback (kifs/trace.cpp). Returns t, or −1.
float trace(vec3 ro, vec3 rd, out Sample hit) {
  float t0, t1;
  hit = Sample(kInf, kInf, vec2(0.0), 0.0);
  if (!rayBox(ro, rd, t0, t1)) return -1.0;
  float t = max(t0, 0.0), tPrev = t, rPrev = 0.0, omega = uOverRelax;
  for (int i = 0; i < uMaxSteps; ++i) {
    Sample s = evaluate(ro + t * rd);
    float r = uLipschitz * s.bound;
    if (omega > 1.0 && r + rPrev < t - tPrev) {
      t = tPrev + rPrev;
      omega = 1.0;
      continue;
    }
    float eps = max(uHitFactor * uPixelAngle * t, kMinHitDistance);
    if (s.surface < eps) {
      hit = s;
      return t;
    }
    tPrev = t;
    rPrev = r;
    t += max(omega * r, eps);
    if (t > t1) return -1.0;
  }
  return -1.0;
}

vec3 normalAt(vec3 p, float h) {
  vec3 k0 = vec3(1, -1, -1), k1 = vec3(-1, -1, 1), k2 = vec3(-1, 1, -1), k3 = vec3(1, 1, 1);
  return normalize(k0 * surfaceAt(p + h * k0) + k1 * surfaceAt(p + h * k1) + k2 * surfaceAt(p + h * k2) +
                   k3 * surfaceAt(p + h * k3));
}

// Penumbra from the closest approach of the shadow ray (Quilez), stepping by the bound.
float softShadow(vec3 ro, vec3 rd, float tmin) {
  float t0, t1;
  if (!rayBox(ro, rd, t0, t1)) return 1.0;
  float res = 1.0, t = max(tmin, t0);
  for (int i = 0; i < 40 && t < t1; ++i) {
    float h = evaluate(ro + t * rd).bound;
    if (h < 0.25 * tmin) return 0.0;
    res = min(res, 10.0 * h / t);
    t += clamp(uLipschitz * h, tmin, uFloors.x);
  }
  return clamp(res, 0.0, 1.0);
}

// Ambient occlusion from three probes along the normal at 1, 3 and 5 steps of 4 % of a storey:
// the former five probes at 1..5 steps (weights 0.6^(i−1)) with each even probe's weight split
// between its neighbours, so the total weight and the reach are the same (docs/kifs.md).
float occlusion(vec3 p, vec3 n) {
  float occ = 0.0, step = 0.04 * uFloors.x;
  const vec3 weight = vec3(1.3, 0.768, 0.2376);
  for (int i = 0; i < 3; ++i) {
    float h = step * float(2 * i + 1);
    occ += weight[i] * max(h - surfaceAt(p + h * n), 0.0) / h;
  }
  return clamp(1.0 - 0.45 * occ, 0.0, 1.0);
}

vec3 palette(float k) {
  return 0.55 + 0.4 * cos(6.2831853 * (vec3(0.0, 0.33, 0.67) + 0.137 * k));
}

vec4 costColor(Sample s) {
  return vec4(float(gEvaluations % 256), float(gEvaluations / 256), s.ids.x + 4.0 * s.ids.y,
              clamp(s.floorIndex + 128.0, 0.0, 255.0)) / 255.0;
}

void main() {
  vec2 pixel = gl_FragCoord.xy - uViewport.xy;
  vec2 ndc = 2.0 * pixel / uViewport.zw - 1.0;
  vec4 far = uInvViewProj * vec4(ndc, 1.0, 1.0);
  vec3 ro = uEye;
  vec3 rd = normalize(far.xyz / far.w - uEye);
  if (uOrtho != 0) {
    vec4 near = uInvViewProj * vec4(ndc, -1.0, 1.0);
    vec3 n3 = near.xyz / near.w;
    rd = normalize(far.xyz / far.w - n3);
    ro = n3 + dot(uEye - n3, rd) * rd;  // where the pixel's ray crosses the eye's plane
  }
  Sample s;
  float t = trace(ro, rd, s);
  if (t < 0.0) {
    if (uMode != 3) discard;
    fragColor = costColor(s);
    gl_FragDepth = 1.0;
    return;
  }
  vec3 p = ro + t * rd;
  vec4 clip = uViewProj * vec4(p, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;

  float footprint = uPixelAngle * t;
  vec3 n = normalAt(p, 0.5 * footprint);
  if (dot(n, rd) > 0.0) n = -n;
  vec3 base = vec3(0.80, 0.76, 0.69);
  if (uMode == 1) base = palette(s.ids.x + 4.0 * s.ids.y);
  if (uMode == 2) base = palette(3.0 * s.floorIndex);
  float sun = max(dot(n, uSunDir), 0.0);
  bool preview = uMode == 4;
  if (sun > 0.0 && !preview) sun *= softShadow(p + 2.0 * footprint * n, uSunDir, 2.0 * footprint);
  float ao = preview ? 1.0 : occlusion(p, n);
  float sky = 0.5 + 0.5 * n.z;
  vec3 light = vec3(1.0, 0.96, 0.88) * sun * 0.85 + ao * mix(vec3(0.22, 0.21, 0.2), vec3(0.40, 0.45, 0.52), sky);
  vec3 c = base * light;
  fragColor = vec4(pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
  if (uMode == 3) fragColor = costColor(s);
}
