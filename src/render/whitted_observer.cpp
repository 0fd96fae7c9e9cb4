#include "render/whitted_observer.h"

namespace rayvec {

const char* ray_kind_name(RayKind kind) {
  switch (kind) {
    case RayKind::camera: return "camera";
    case RayKind::shadow: return "shadow";
    case RayKind::reflection: return "reflection";
    case RayKind::refraction: return "refraction";
  }
  return "?";
}

const char* skip_reason_name(SkipReason reason) {
  switch (reason) {
    case SkipReason::max_depth: return "max_depth";
    case SkipReason::contribution_cutoff: return "contribution_cutoff";
    case SkipReason::total_internal_reflection: return "total_internal_reflection";
    case SkipReason::effect_off: return "effect_off";
  }
  return "?";
}

}  // namespace rayvec
