// SurfacePoint: what shading needs to know about a hit — position, normals, texture coordinates,
// material — in the orientation the shaders expect (normals facing the incoming ray).
#pragma once
#include <cstddef>
#include <vector>

#include "rays/ray.h"
#include "scene/scene.h"

namespace rayvec {

struct SurfacePoint {
  Vec3f p;               // from barycentrics: v0 + u·e1 + v·e2 (accurate to a few ulps of the vertices)
  Vec3f ng;              // unit geometric normal, flipped to face the incoming ray
  Vec3f ns;              // unit shading normal (interpolated vn, else ng), on the same side as ng
  bool entering;         // the ray arrives on the front (counter-clockwise, outward) side
  float u = 0, v = 0;    // texture coordinates (0 when the OBJ gives none)
  Vec3f color{1, 1, 1};  // the vertex colours interpolated (white when the scene has none)
  int32_t material = 0;
};

// The unit geometric normal of every triangle of a scene, with surface_point's arithmetic (the same
// bits), so that shading a hit only looks it up: 12 bytes a triangle, made once per render on the
// render's threads. It pays where a render shades more hits than the mesh has triangles, hence
// worth_it: at most as many triangles as the render has camera rays — and, being only a shortcut,
// no more than a quarter of the memory still available (`available` bytes; 0 = unknown).
class TriangleNormals {
 public:
  TriangleNormals() = default;  // none: surface_point computes each hit's
  explicit TriangleNormals(const Scene& scene);
  static bool worth_it(std::size_t triangles, std::size_t camera_rays, std::size_t available) {
    return triangles <= camera_rays && (available == 0 || triangles * sizeof(Vec3f) <= available / 4);
  }
  // The table for a render of the scene's camera at `spp` samples a pixel where worth_it, else none.
  static TriangleNormals for_render(const Scene& scene, int spp, std::size_t available);
  bool empty() const { return normals_.empty(); }
  Vec3f operator[](std::size_t t) const { return normals_[t]; }

 private:
  std::vector<Vec3f> normals_;
};

// `normals`: the scene's TriangleNormals, or null (or empty) to compute the hit triangle's. Written
// into `s`: a caller that keeps the point reads it where it was stored once, not a returned copy.
void surface_point(const Scene& scene, const Ray& ray, const Hit& hit, const TriangleNormals* normals,
                   SurfacePoint& s);
inline SurfacePoint surface_point(const Scene& scene, const Ray& ray, const Hit& hit,
                                  const TriangleNormals* normals = nullptr) {
  SurfacePoint s;
  surface_point(scene, ray, hit, normals, s);
  return s;
}

// Diffuse albedo at the point: Kd, times the map_Kd texture (bilinear, repeating, at the texture
// coordinates scaled and offset as the MTL's `-s` and `-o` say) when present, times the vertex
// colour.
Vec3f diffuse_albedo(const Scene& scene, const SurfacePoint& s);

}  // namespace rayvec
