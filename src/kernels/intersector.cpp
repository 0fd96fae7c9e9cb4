#include "kernels/intersector.h"

namespace rayvec {

const char* intersector_name(Intersector i) {
  switch (i) {
    case Intersector::paper: return "paper";
    case Intersector::mt: return "mt";
    case Intersector::mt64: return "mt64";
    case Intersector::watertight: return "watertight";
    case Intersector::watertight64: return "watertight64";
  }
  return "?";
}

std::optional<Intersector> parse_intersector(std::string_view name) {
  for (Intersector i : kAllIntersectors)
    if (name == intersector_name(i)) return i;
  return std::nullopt;
}

}  // namespace rayvec
