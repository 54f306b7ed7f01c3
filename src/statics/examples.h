#pragma once
// The paper's example structures as parametric models built from the templates (Whiting et
// al. 2009): the stacked tower (Fig. 11), the arch on two columns (Fig. 8), the barrel vault
// on buttressed walls (Fig. 13) and a Bezier arch (Fig. 12).
#include "statics/parameters.h"

#include <string>
#include <vector>

namespace corbel::statics {

// Fig. 11: 16 levels, each four posts under a slab of two blocks (96 blocks). Level k sits
// on level k − 1 moved by (xk, yk) (parameters x1..x16, y1..y16, the 32 of the paper); they
// start leaning (xk = 0.12), which does not stand. Free by default: all 32 in [−0.2, 0.2].
ParametricModel towerExample();

// Fig. 8: a semicircular arch (radius 1, `voussoirs` blocks, `thickness`) springing from the
// tops of two square columns of `columnWidth` and `columnHeight`, centred under the
// springings, on ground. Free by default: thickness and columnWidth.
ParametricModel archOnColumnsExample();

// Fig. 13: a barrel vault (`radius`, `thickness`, `rings` along its `length`) on two walls of
// `wallThickness` and `wallHeight` in `courses`, each backed by a buttress of
// `buttressWidth` per ring (140 blocks by default). Free by default: buttressWidth.
ParametricModel barrelVaultExample();

// Fig. 13 with flying buttresses: the vault of barrelVaultExample on walls 3 m high, each
// ring's wall propped by a quarter-arc flyer (5 voussoirs) whose head meets the wall's top and
// whose springing sits on a pier of 3 courses; `reach` is the flyers' radius (their reach from
// the wall and their rise). 180 blocks. Free by default: reach in [0.3, 2.5].
ParametricModel flyingButtressVaultExample();

// Fig. 12: a thin arch (16 voussoirs, 0.05 m, span 2 m, crown 1.2 m) whose centreline is a
// cubic Bezier with inner control points at x1, x2 (starting at ∓1: a round arch that does not
// stand). Free by default: x1 in [−1.5, 0.5], x2 in [−0.5, 1.5].
ParametricModel bezierArchExample();

// Fig. 9 (after the Sainte Chapelle, 486 blocks in Table 1): a hall of `bays` bays under a
// barrel vault (two rings a bay), each side wall a bay of courses with a window (lintel in the
// top course), piers of `buttressWidth` × `buttressDepth` standing out at the joints between
// bays. 480 blocks by default. Free by default: buttressWidth, buttressDepth, wallThickness and
// wallHeight (the paper's column dimensions and overall height). The paper's groined vault is
// a barrel vault here.
ParametricModel chapelExample();

// Fig. 1 (after Cluny, 986 blocks in Table 1): flyingButtressVaultExample as a nave of 26
// bays, 8 m walls and an 8 m span (988 blocks). Free by default: wallThickness, pierWidth,
// flyerThickness and reach (Table 1's four parameters).
ParametricModel abbeyExample();

// Fig. 10 (c): a hemispherical dome (`rings` rings of `segments` voussoirs up to a 10° oculus)
// on a round drum of `courses` courses, propped by `flyers` radial flying buttresses whose
// heads lie against the drum's faces at its top and whose piers stand on the ground. Every
// other segment of the drum (those between the flyers) has a window of `windowWidth` from
// course `windowSill` to a lintel in course `windowHead` (drumBlocks). With `hall` = 1 the
// drum stands on a square hall (squareHallBlocks: walls with a window each, corner slabs
// under the drum; hall.h). 296 blocks by default (0.5 m windows, no hall). Free by default:
// drumThickness and reach.
ParametricModel mosqueExample();

// Fig. 10 (a, d): mosqueExample with its square hall and no flyers, a 0.5 m drum and 0.9 m
// windows (which do not stand). Free by default: windowWidth in [0.1, 0.9] (the search
// narrows the windows).
ParametricModel mosqueHallExample();

// A groin vault (groin.h) of `voussoirs` rows per web and `courses` along each web's axis on
// four square corner piers of `pierWidth` and `pierHeight` in `drums` courses (12 voussoirs,
// 3 courses, 2 drums: 4 webs of 18 blocks and 8 drums, 80 blocks), with diagonal ribs when
// `ribs` is 1 (4 ribs of 6 voussoirs in halves: 48 blocks more). Free by default: thickness
// and pierWidth.
ParametricModel groinVaultExample();

std::vector<std::string> exampleNames();
// An example, or a template alone (statics/template_models.h), by name. Throws corbel::Error
// for an unknown name, listing the known ones.
ParametricModel exampleByName(const std::string& name);

}  // namespace corbel::statics
