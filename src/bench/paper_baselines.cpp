// Sena et al. (2018) Figure 1 as scalar code, in the paper's two layouts (see paper_baselines.h).
#include "bench/paper_baselines.h"

#include "geometry/triangle_mesh.h"

namespace rayvec {
namespace {

constexpr float kEpsilon = 1e-6f;  // Figure 4's SET(1.0e-6) in float lanes

struct Best {
  float t, u, v;
  int32_t tri;
};

// Figure 1, lines 15–33, for one ray and one triangle: updates `best` when the triangle is hit
// nearer. Every comparison is written so that NaN fails it (as the vector kernels' ordered compares
// do), hence `!(u >= 0 && u <= 1)` rather than the paper's `u < 0 || u > 1`.
inline void test_triangle(float ox, float oy, float oz, float dx, float dy, float dz, float tmin, float tmax,
                          float v0x, float v0y, float v0z, float v1x, float v1y, float v1z, float v2x,
                          float v2y, float v2z, int32_t id, Best& best) {
  // edge1 = v1 - v0, edge2 = v2 - v0, h = d × edge2, a = edge1 · h
  const float e1x = v1x - v0x, e1y = v1y - v0y, e1z = v1z - v0z;
  const float e2x = v2x - v0x, e2y = v2y - v0y, e2z = v2z - v0z;
  const float hx = dy * e2z - dz * e2y, hy = dz * e2x - dx * e2z, hz = dx * e2y - dy * e2x;
  const float a = e1x * hx + e1y * hy + e1z * hz;
  if (!((a < 0.0f ? -a : a) >= kEpsilon)) return;
  const float f = 1.0f / a;
  // u
  const float sx = ox - v0x, sy = oy - v0y, sz = oz - v0z;
  const float u = f * (sx * hx + sy * hy + sz * hz);
  if (!(u >= 0.0f && u <= 1.0f)) return;
  // v
  const float qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
  const float v = f * (dx * qx + dy * qy + dz * qz);
  if (!(v >= 0.0f && u + v <= 1.0f)) return;
  // depth test: strict against the best so far, so equal t keeps the lower id
  const float t = f * (e2x * qx + e2y * qy + e2z * qz);
  if (t > kEpsilon && t >= tmin && t <= tmax && t < best.t) best = Best{t, u, v, id};
}

Hit to_hit(const Best& b) { return b.tri < 0 ? Hit{} : Hit{b.t, b.u, b.v, b.tri}; }

}  // namespace

PaperAosTriangles paper_aos_triangles(const TriangleMesh& mesh) {
  PaperAosTriangles out;
  out.xyz.reserve(mesh.size() * 9);
  for (std::size_t i = 0; i < mesh.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const Vec3f p = mesh.vertex(i, c);
      out.xyz.insert(out.xyz.end(), {p.x, p.y, p.z});
    }
  return out;
}

PaperSoaTriangles paper_soa_triangles(const TriangleMesh& mesh) {
  PaperSoaTriangles out;
  std::vector<float>* arrays[9] = {&out.v0x, &out.v0y, &out.v0z, &out.v1x, &out.v1y,
                                   &out.v1z, &out.v2x, &out.v2y, &out.v2z};
  for (auto* a : arrays) a->reserve(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const Vec3f p = mesh.vertex(i, c);
      arrays[3 * c]->push_back(p.x);
      arrays[3 * c + 1]->push_back(p.y);
      arrays[3 * c + 2]->push_back(p.z);
    }
  return out;
}

void closest_original(const PaperAosTriangles& tris, std::span<const Ray> rays, std::size_t begin,
                      std::size_t end, std::span<Hit> hits) {
  const float* p = tris.xyz.data();
  const std::size_t n = tris.size();
  for (std::size_t r = begin; r < end; ++r) {
    const Ray& ray = rays[r];
    Best best{kInf, 0.0f, 0.0f, -1};
    for (std::size_t i = 0; i < n; ++i) {
      const float* t = p + 9 * i;
      test_triangle(ray.org.x, ray.org.y, ray.org.z, ray.dir.x, ray.dir.y, ray.dir.z, ray.tmin, ray.tmax,
                    t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8], static_cast<int32_t>(i), best);
    }
    hits[r] = to_hit(best);
  }
}

void closest_optimized(const PaperSoaTriangles& tris, const RayBatch& rays, std::size_t begin,
                       std::size_t end, std::span<Hit> hits) {
  const std::size_t n = tris.size();
  const float *v0x = tris.v0x.data(), *v0y = tris.v0y.data(), *v0z = tris.v0z.data();
  const float *v1x = tris.v1x.data(), *v1y = tris.v1y.data(), *v1z = tris.v1z.data();
  const float *v2x = tris.v2x.data(), *v2y = tris.v2y.data(), *v2z = tris.v2z.data();
  for (std::size_t r = begin; r < end; ++r) {
    const float ox = rays.ox[r], oy = rays.oy[r], oz = rays.oz[r];
    const float dx = rays.dx[r], dy = rays.dy[r], dz = rays.dz[r];
    const float tmin = rays.tmin[r], tmax = rays.tmax[r];
    Best best{kInf, 0.0f, 0.0f, -1};
    for (std::size_t i = 0; i < n; ++i)
      test_triangle(ox, oy, oz, dx, dy, dz, tmin, tmax, v0x[i], v0y[i], v0z[i], v1x[i], v1y[i], v1z[i],
                    v2x[i], v2y[i], v2z[i], static_cast<int32_t>(i), best);
    hits[r] = to_hit(best);
  }
}

}  // namespace rayvec
