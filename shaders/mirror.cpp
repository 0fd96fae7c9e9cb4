#include "shaders/mirror.h"

namespace rayvec::shaders {

Vec3f mirror_direction(Vec3f d, Vec3f n) { return d - n * (2.0f * dot(d, n)); }

}  // namespace rayvec::shaders
