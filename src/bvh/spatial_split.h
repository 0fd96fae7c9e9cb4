// Spatial splits for the binned SAH builder (Stich, Friedrich & Dietrich 2009, "Spatial Splits in
// Bounding Volume Hierarchies"): besides partitioning a node's references by centroid, the builder
// may cut space at a plane; a triangle that straddles it is referenced on both sides, each reference
// bounding only the triangle's part on its side. Where object-split children overlap (long or
// crossing triangles), this gives tighter boxes for some duplicated references.
#pragma once
#include <cstdint>
#include <vector>

#include "bvh/build_prim.h"
#include "geometry/bbox.h"

namespace rayvec {

struct TriangleMesh;

struct SpatialSplit {
  int axis = -1;                 // -1: none found
  int plane = 0;                 // the cut lies between bins plane − 1 and plane (1 ≤ plane < bins)
  float cost = 0;                // Σ over the sides of half area · leaf cost of its count
  uint32_t left = 0, right = 0;  // references on each side, as binned (an upper bound of each)
};

class SpatialSplitter {
 public:
  // `bins` planes per axis minus one are tried; leaf_block as SahConfig::leaf_block.
  SpatialSplitter(const TriangleMesh& mesh, int bins, uint32_t leaf_block);

  // The cheapest split of refs[0, n) (within `box`, their bounds) at one of the bin planes of each
  // axis, both sides holding fewer than n references and at least one, and at most `room`
  // references more than n in all; axis −1 when there is none.
  SpatialSplit find(const BuildPrim* refs, uint32_t n, const BBox& box, uint32_t room) const;

  // Applies `split` (from find with the same refs and box): writes the left side's references to
  // refs[0, returned count) and the right side's to `right`. A straddling reference is clipped to
  // each side where its triangle has a part there; the others keep their box. Each side gets at
  // most the references find() counted for it (both classify a reference by the same bins).
  uint32_t partition(BuildPrim* refs, uint32_t n, const BBox& box, const SpatialSplit& split,
                     std::vector<BuildPrim>& right) const;

  // The parts of r's triangle on each side of the plane x_axis = at, each bounded within r's box;
  // false for a side with no part (its box is then empty). Conservative: computed crossing points
  // are widened by 2^-20 of the edge's coordinates (some 16 ulps), so a box never misses a point of
  // the triangle's part.
  void clip(const BuildPrim& r, int axis, float at, BuildPrim& left, BuildPrim& right, bool& has_left,
            bool& has_right) const;

 private:
  float plane_at(const BBox& box, int axis, int k) const;
  void bin_span(const BuildPrim& r, const BBox& box, int axis, bool splittable, int& first, int& last) const;
  float leaf_cost(uint32_t n) const { return float((n + leaf_block_ - 1) / leaf_block_); }

  const TriangleMesh& mesh_;
  int bins_;
  uint32_t leaf_block_;
};

}  // namespace rayvec
