#pragma once
// Masonry template: the semicircular arch of voussoirs with radial joints on rigid ground
// (Whiting et al. 2009, Sec. 3.3 validation).
#include "statics/model.h"

namespace corbel::statics {

struct ArchSpec {
  int blocks = 100;         // voussoirs
  double radius = 1.0;      // centreline radius, m
  double thickness = 0.2;   // radial thickness, m
  double depth = 0.5;       // along the arch's axis (y), m
  double tiltDeg = 0.0;     // ground tilt about the axis: gravity rotated towards +x
  double density = 2400.0;  // kg/m³
};

// Voussoir i spans angles [iπ/N, (i+1)π/N] in the xz-plane, its joints radial planes through
// the axis; intrados and extrados are chords at radius R ∓ t/2. Block N is the fixed ground
// (its top face at z = 0). Throws corbel::Error for a spec that makes no arch.
Assembly semicircularArch(const ArchSpec& spec);

}  // namespace corbel::statics
