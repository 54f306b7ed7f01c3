#pragma once
// Masonry templates: arches of voussoirs with radial joints (Whiting et al. 2009, Sec. 2,
// Fig. 4; the semicircular arch of the Sec. 3.3 validation and the gothic pointed arch).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

// A joint between voussoirs in the xz-plane: its intrados and extrados points (x, z).
struct ArchJoint {
  Vec2 inner, outer;
};

// Voussoir i lies between joints i and i + 1, swept along y over [y0, y1].
std::vector<Block> voussoirs(const std::vector<ArchJoint>& joints, double y0, double y1, double density);

struct ArchSpec {
  int blocks = 100;         // voussoirs
  double radius = 1.0;      // centreline radius, m
  double thickness = 0.2;   // radial thickness, m
  double depth = 0.5;       // along the arch's axis (y), m
  double tiltDeg = 0.0;     // ground tilt about the axis: gravity rotated towards +x
  double density = 2400.0;  // kg/m³
};

// Checks a spec's numbers; throws corbel::Error naming the bad one.
void validateArchSpec(const ArchSpec& spec);

// Joint k of the semicircular arch lies on the radial line at angle kπ/N, from radius R − t/2
// to R + t/2; intrados and extrados are chords. Springings at x = ±R on z = 0.
std::vector<ArchJoint> semicircularJoints(const ArchSpec& spec);

// The semicircular arch's voussoirs (y ∈ [−depth/2, depth/2]) without ground.
std::vector<Block> semicircularArchBlocks(const ArchSpec& spec);

// Voussoir i spans angles [iπ/N, (i+1)π/N] in the xz-plane. Block N is the fixed ground (its
// top face at z = 0). Throws corbel::Error for a spec that makes no arch.
Assembly semicircularArch(const ArchSpec& spec);

// The pointed (gothic) arch: each half is an arc of radius ρ = radiusRatio·R whose centre lies
// on the springing line at distance ρ − R on the other side, so the centreline springs at
// x = ±R and the halves meet at the crown x = 0. radiusRatio 1 is the semicircular arch, 2 the
// equilateral arch. Joints are radial to each half's centre, evenly spread in angle up to
// where the intrados meets the crown plane; the crown joint is vertical.
struct PointedArchSpec {
  int blocks = 20;            // voussoirs, even (half on each side of the crown)
  double radius = 1.0;        // half the centreline span, m
  double radiusRatio = 2.0;   // arc radius / radius, ≥ 1
  double thickness = 0.2;     // m, measured along the joints
  double depth = 0.5;         // m
  double tiltDeg = 0.0;
  double density = 2400.0;
};

std::vector<ArchJoint> pointedJoints(const PointedArchSpec& spec);
std::vector<Block> pointedArchBlocks(const PointedArchSpec& spec);
Assembly pointedArch(const PointedArchSpec& spec);  // on fixed ground at z = 0

// The Bezier arch of Fig. 12: the centreline is the cubic Bezier from (−R, 0) to (R, 0) with
// inner control points (x1, 1) and (x2, 1), its height then scaled to `height`; the two inner
// control points' horizontal positions are the shape's parameters. Joint k sits at Bezier
// parameter k/N across the centreline (perpendicular to its tangent), except the springings,
// which are horizontal joints on z = 0 centred on ±R.
struct BezierArchSpec {
  int blocks = 20;
  double radius = 1.0;     // half the centreline span, m
  double height = 1.0;     // of the centreline's crown, m
  double x1 = -1.0, x2 = 1.0;  // the inner control points' x (x1 = −R, x2 = R: a tall, round arch)
  double thickness = 0.1;  // across the centreline, m
  double depth = 0.5;
  double density = 2400.0;
};

std::vector<ArchJoint> bezierJoints(const BezierArchSpec& spec);
std::vector<Block> bezierArchBlocks(const BezierArchSpec& spec);
Assembly bezierArch(const BezierArchSpec& spec);  // on fixed ground at z = 0

}  // namespace corbel::statics
