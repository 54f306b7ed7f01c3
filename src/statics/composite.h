#pragma once
// Several masonry objects analysed as one structure (Whiting et al. 2009 compose a building of
// templates; here each template may be an object of its own, placed by the artist): an arcade
// is a wall, columns and arches that carry one another where their faces meet.
#include "core/placement.h"
#include "statics/parameters.h"

#include <string>
#include <vector>

namespace corbel::statics {

struct CompositePart {
  std::string name;       // the object's: its parameters become "name/param", its blocks "name/block"
  ParametricModel model;  // the object's model (statics::modelOf, its loads included)
  Placement placement;    // where the object stands
};

// One model of every part: the parameters of all parts under their prefixed names (values as
// the parts have them), and a build that places each part's free blocks (loads moved and turned
// with them) and puts one fixed ground slab under them all, its top at the lowest point of any
// free block and 1 m wider on each side. The parts' own ground slabs are dropped: a part standing
// on another (an arch on columns) would otherwise bring a slab where the other part is.
// Throws corbel::Error for no parts, a name used twice or with a '/', or parts whose gravity
// differs.
ParametricModel compositeModel(std::vector<CompositePart> parts);

// The part and the parameter of a composite parameter name ("Arch/thickness").
std::pair<std::string, std::string> splitCompositeName(const std::string& name);

}  // namespace corbel::statics
