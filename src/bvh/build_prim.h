// BuildPrim: one reference of the SAH builder (bvh/binary_bvh.cpp) — a box and the id of the
// triangle it bounds. A triangle has one reference, or more after spatial splits
// (bvh/spatial_split.h), each bounding the part of the triangle on its side of the split planes.
#pragma once
#include <cstdint>

namespace rayvec {

// Moved (not indexed) by the builder's partitions so every pass reads memory in order.
struct alignas(32) BuildPrim {
  float lo[3];
  uint32_t id;
  float hi[3];
  float pad;  // 0, so lane 3 of the binning's 4-lane centroid stays 0
  float centroid(int a) const { return (lo[a] + hi[a]) * 0.5f; }
};

}  // namespace rayvec
