#include "core/stone_walls.h"

namespace corbel {

const char* openingHeadName(OpeningHead head) { return head == OpeningHead::FlatArch ? "flat_arch" : "lintel"; }

bool openingHeadFromName(const std::string& name, OpeningHead& head) {
  if (name == "lintel") head = OpeningHead::Lintel;
  else if (name == "flat_arch") head = OpeningHead::FlatArch;
  else return false;
  return true;
}

}  // namespace corbel
