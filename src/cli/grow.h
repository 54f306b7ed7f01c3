#pragma once
// corbel-cli grow: runs the growth kernel on a site file (docs/growth.md).

#include "core/scene.h"
#include "growth/site.h"
#include "growth/unit.h"

#include <vector>

namespace corbel::cli {

// Units (kind unit), cores and circulation (kind mass) as Scene objects, ids from 1.
Scene modelScene(const growth::Site& site, const std::vector<growth::Unit>& units);

// argv[1] is "grow". Returns the exit code (0 ok, 1 bad input, 2 bad command line); input
// faults are thrown as corbel::Error for main to report.
int grow(int argc, char** argv);

}  // namespace corbel::cli
