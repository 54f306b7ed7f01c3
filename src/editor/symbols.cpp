#include "editor/symbols.h"

#include <utility>

namespace corbel::editor {

const char* symbolWords(std::string_view label) {
  static const std::pair<std::string_view, const char*> table[] = {
      // KIFS (McGraw): Algorithm 1, Algorithm 2 (the facade fold), Eq. 4-6.
      {"w (bay)", "w: the facade's period, the width of one bay (Algorithm 2)."},
      {"r1 (width)", "r1: the first width of the facade fold (Algorithm 2, r_1), a fraction of the bay: where a bay splits into facade regions."},
      {"r2 (width)", "r2: the second width of the facade fold (Algorithm 2, r_2), splitting the regions again."},
      {"r3 (width)", "r3: the third width of the facade fold (Algorithm 2, r_3)."},
      {"h (storey)", "h: the storey height (Eq. 4), metres."},
      {"y0 (storey start)", "y0: where the storeys start (Eq. 4): shifts which slab of the fractal each storey shows, metres."},
      {"s_y (storey scale)", "s_y: how tall a slab of the fractal one storey shows (Eq. 4: y_f = s_y mod(y - y0, h) / h)."},
      {"z0", "z0: the centre of the ring along z (Eq. 6), metres."},
      {"a1", "a1: how much the fractal's scale changes from one facade region to the next (s = a1·id + a2)."},
      {"a2", "a2: the fractal's scale in facade region 0 (s = a1·id + a2)."},
      {"b1", "b1: how much the fractal's offset changes from one facade region to the next (t = b1·id + b2)."},
      {"b2", "b2: the fractal's offset in facade region 0 (t = b1·id + b2)."},
      {"x_c", "x_c: x of the centre each fold of Algorithm 1 scales about."},
      {"y_c", "y_c: y of the centre each fold of Algorithm 1 scales about."},
      {"z_c", "z_c: z of the centre each fold of Algorithm 1 scales about."},
      {"R2 theta (deg)", "R2: the turn after each fold of Algorithm 1, its angle θ about the vertical."},
      {"s (scale)", "s: how much each fold of Algorithm 1 scales the space (the fractal's ratio)."},
      {"R1 x (deg)", "R1: the turn before each fold of Algorithm 1, about x."},
      {"R1 y (deg)", "R1: the turn before each fold of Algorithm 1, about the vertical."},
      {"R1 z (deg)", "R1: the turn before each fold of Algorithm 1, about z."},
      {"M (iterations)", "M: how many times Algorithm 1 folds the space (more: finer detail, slower)."},
      {"Bailout", "Folding stops once a point lies this far out (|p|² > bailout)."},
      {"s_theta", "s_θ: building units per radian round the ring (Eq. 5): how far the facade stretches round it."},
      {"c_theta", "c_θ: the angle the ring starts at (Eq. 5), radians."},
      {"s_r", "s_r: how the radius scales into the building's depth (Eq. 6)."},
      {"c_r", "c_r: the radius offset (Eq. 6): minus the ring's radius in building units."},
      {"Shell", "The inner shell lies this far inside the outer one: the walls' thickness."},
      // Form completion (Ng, Ch. 7).
      {"Seeds N", "N: how many seeds (entrances) the forms grow from."},
      {"LO", "LO: the least form complexity F_q of the forms wanted (0 = simplest)."},
      {"HI", "HI: the largest form complexity F_q of the forms wanted."},
      {"Forms K", "K: how many distinct forms to generate."},
      // Statics (Whiting et al. 2009).
      {"y/W²", "y/W²: the tension the structure needs to stand, squared, over its weight squared; 0 means it stands."},
  };
  for (const auto& [key, words] : table)
    if (key == label) return words;
  return nullptr;
}

}  // namespace corbel::editor
