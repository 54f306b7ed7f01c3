#pragma once
// The paper's example structures as parametric models built from the templates (Whiting et
// al. 2009): the stacked tower (Fig. 11), the arch on two columns (Fig. 8) and the barrel
// vault on buttressed walls (Fig. 13).
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

std::vector<std::string> exampleNames();
// Throws corbel::Error for an unknown name, listing the known ones.
ParametricModel exampleByName(const std::string& name);

}  // namespace corbel::statics
