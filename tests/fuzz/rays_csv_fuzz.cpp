// Fuzzes the RAYS.csv reader (parse_rays_csv). Only InputError may escape the parser; every ray it
// returns must satisfy the documented contract (finite origin and non-zero finite direction,
// tmin <= tmax, neither NaN).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/input_error.h"
#include "io/rays_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const rayvec::RayBatch rays = rayvec::parse_rays_csv(text, "fuzz.csv");
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const rayvec::Ray r = rays[i];
      const float f[] = {r.org.x, r.org.y, r.org.z, r.dir.x, r.dir.y, r.dir.z};
      for (float x : f)
        if (!std::isfinite(x)) __builtin_trap();
      if (r.dir.x == 0 && r.dir.y == 0 && r.dir.z == 0) __builtin_trap();
      if (!(r.tmin <= r.tmax)) __builtin_trap();
    }
  } catch (const rayvec::InputError&) {}
  return 0;
}
