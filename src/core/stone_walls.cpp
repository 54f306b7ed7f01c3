#include "core/stone_walls.h"

namespace corbel {

const char* openingHeadName(OpeningHead head) {
  switch (head) {
    case OpeningHead::FlatArch: return "flat_arch";
    case OpeningHead::SemicircularArch: return "semicircular_arch";
    case OpeningHead::Lintel: break;
  }
  return "lintel";
}

bool openingHeadFromName(const std::string& name, OpeningHead& head) {
  if (name == "lintel") head = OpeningHead::Lintel;
  else if (name == "flat_arch") head = OpeningHead::FlatArch;
  else if (name == "semicircular_arch") head = OpeningHead::SemicircularArch;
  else return false;
  return true;
}

}  // namespace corbel
