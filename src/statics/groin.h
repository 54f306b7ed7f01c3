#pragma once
// Masonry template: the groin vault, two barrel vaults of the same rise crossing at right
// angles over a bay, on four corner piers (Whiting et al. 2009, Fig. 9's groined vault).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct GroinVaultSpec {
  int voussoirs = 8;        // per arch (each web is a semicircular arch of this many rows)
  int courses = 3;          // transverse joints along each web's axis, from the centre to the bay's face
  double radius = 2.0;      // centreline radius of both barrels (the rise of the centreline), m
  double thickness = 0.25;  // m
  double stretch = 1.0;     // bay length along x over its length along y (1: a square bay)
  double pierHeight = 0.0;  // 0: the springings sit on the ground
  double pierWidth = 0.5;   // side of the square piers along y (× stretch along x), at least the thickness, m
  int pierDrums = 2;        // courses of each pier
  bool ribs = false;        // diagonal ribs under the groins (needs an even number of voussoirs)
  double ribWidth = 0.2;    // across the diagonal, at most thickness·√2/2, m
  double ribDepth = 0.15;   // below the intrados, m
  double density = 2400.0;
};

// The four webs, springing at z = 0, over the bay |x| ≤ s·(R + t/2), |y| ≤ R + t/2 (s the
// stretch). Built for s = 1 and then scaled along x. The web of +x is the barrel whose axis is
// x, restricted to x ≥ |y|; its rows are the semicircular arch's voussoirs (section Q_k between
// the radial joints at kπ/N, (k+1)π/N, intrados and extrados chords of radii R ∓ t/2). Row k
// of the web is cut by the transverse planes x = j·(R + t/2)/courses: the groin block runs from
// the diagonal planes x = ±y to the first such plane at or beyond max |y| of Q_k, the rest of
// the row is straight courses between consecutive planes. Every block is the convex
// intersection of half-spaces (prism of Q_k ∩ x ≥ y ∩ x ≥ −y ∩ slab), so all faces are plane;
// the webs of ±y are the web of +x turned by ±90° and its mirror, so two webs' groin blocks
// meet face to face on the diagonal planes, row k against row N − 1 − k.
// With ribs, each half-diagonal carries a rib of N/2 voussoirs, each split along the diagonal
// plane into two halves: the half under the web of +x, row k, is {(y, z) between the radial
// joints of row k and between its intrados chord and that chord moved ribDepth towards the
// axis, 0 ≤ x − y ≤ ribWidth/√2}; the other half is its mirror in x = y. A half's top lies on
// its web's intrados chord, so it touches the groin block (and any straight course) above it;
// the halves of neighbouring quadrants meet on x = 0 and y = 0 at the crown.
// Throws corbel::Error for a bad spec.
std::vector<Block> groinVaultBlocks(const GroinVaultSpec& spec);

// The four corner piers (box drums of pierWidth·stretch × pierWidth centred under the
// springing squares at (±s·R, ±R)), from z = 0 to pierHeight; empty when pierHeight is 0.
std::vector<Block> groinVaultPiers(const GroinVaultSpec& spec);

// The vault on its piers (raised by pierHeight), on fixed ground.
Assembly groinVault(const GroinVaultSpec& spec);

// The ribs' volume: 4 N (w/√2) tan(π/2N) [(ri c)² − (ri c − d)²], c = cos(π/2N), w, d the
// rib's width and depth (each half-rib voussoir is its trapezoid section swept w/√2 along x).
double groinVaultRibVolume(const GroinVaultSpec& spec);

// The volume of the true (unfaceted) groin-vault shell, s·[2π ro (ro² − ri²) − (8/3)(ro³ − ri³)]:
// two half-cylindrical shells of length 2 ro less their common part.
double groinVaultShellVolume(const GroinVaultSpec& spec);

}  // namespace corbel::statics
