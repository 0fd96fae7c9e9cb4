// HITS.csv: what `rayvec hits` writes (format in docs/formats.md).
//   closest hits:  header `ray,tri,t,u,v`, one line per ray: 0-based ray index, triangle id (-1 on
//                  a miss), t (`inf` on a miss), barycentrics u v (0 on a miss).
//   any hit:       header `ray,hit`, one line per ray, hit 0 or 1.
// Floats are printed in the shortest decimal form that reads back to the same float (std::to_chars;
// at most 9 significant digits, like %.9g but without trailing noise).
#pragma once
#include <cstdint>
#include <span>

#include "rays/ray.h"

namespace rayvec {

class OutputSink;

// Formats in parallel (OpenMP, blocks of rays) and writes in order. RuntimeError on a write failure.
void write_hits_csv(OutputSink& out, std::span<const Hit> hits);
void write_any_hits_csv(OutputSink& out, std::span<const uint8_t> occluded);

}  // namespace rayvec
