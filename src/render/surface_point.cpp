#include "render/surface_point.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>

namespace rayvec {

namespace {

constexpr float kMaxFinite = 3.40282347e+38f;

float max_abs(Vec3f a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }

// A power of two p with m·p in [1, 4) for a positive finite m (in [2^-23, 1) when m is subnormal).
// Scaling by it is exact, so it costs a multiply where dividing by m would cost a division.
float inverse_scale(float m) {
  const int exponent = std::clamp(int(std::bit_cast<uint32_t>(m) >> 23), 1, 253);
  return std::bit_cast<float>(uint32_t(254 - exponent) << 23);
}

// `a` at unit length; a must be nonzero and finite. Scaled first (exactly) so that its squared
// length neither underflows nor overflows float.
Vec3f normalize_any(Vec3f a) {
  const Vec3f b = a * inverse_scale(max_abs(a));
  return b * (1.0f / std::sqrt(dot(b, b)));
}

// The unit normal of a triangle of any size. The edges are scaled (exactly, by powers of two) to a
// largest component in [1, 4) before the cross product: unscaled, its squared length underflows
// float for triangles below about 1e-10 across (and overflows above about 1e19), and normalize()
// then yields NaN or Inf. A zero-area triangle (never hit) gets a zero vector.
Vec3f unit_normal(Vec3f e1, Vec3f e2) {
  const float s1 = max_abs(e1), s2 = max_abs(e2);
  if (!(s1 > 0) || !(s2 > 0) || !(s1 <= kMaxFinite) || !(s2 <= kMaxFinite)) return {0, 0, 0};
  const Vec3f c = cross(e1 * inverse_scale(s1), e2 * inverse_scale(s2));
  const float sc = max_abs(c);
  if (!(sc > 0)) return {0, 0, 0};
  return normalize_any(c);
}

// A texture coordinate wrapped into [0, 1] (repeating textures); 0 where it is not finite (a
// coordinate near float's limit times a large `-s` scale overflows).
float repeat(float t) { return std::isfinite(t) ? t - std::floor(t) : 0.0f; }

}  // namespace

TriangleNormals::TriangleNormals(const Scene& scene) : normals_(scene.mesh.size()) {
  const auto n = static_cast<std::int64_t>(normals_.size());
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (std::int64_t k = 0; k < n; ++k) {
    const auto t = static_cast<std::size_t>(k);
    const Vec3f v0 = scene.mesh.vertex(t, 0);
    normals_[t] = unit_normal(scene.mesh.vertex(t, 1) - v0, scene.mesh.vertex(t, 2) - v0);
  }
}

TriangleNormals TriangleNormals::for_render(const Scene& scene, int spp, std::size_t available) {
  const std::size_t camera_rays =
      std::size_t(scene.camera.width) * std::size_t(scene.camera.height) * std::size_t(std::max(1, spp));
  return worth_it(scene.mesh.size(), camera_rays, available) ? TriangleNormals(scene) : TriangleNormals();
}

void surface_point(const Scene& scene, const Ray& ray, const Hit& hit, const TriangleNormals* normals,
                   SurfacePoint& s) {
  // Formed in locals and stored once at the end: fields read back right after their stores would
  // wait on store forwarding.
  const std::size_t t = static_cast<std::size_t>(hit.tri);
  const Vec3f v0 = scene.mesh.vertex(t, 0), e1 = scene.mesh.vertex(t, 1) - v0,
              e2 = scene.mesh.vertex(t, 2) - v0;
  Vec3f ng = normals && !normals->empty() ? (*normals)[t] : unit_normal(e1, e2);
  if (ng == Vec3f{0, 0, 0}) ng = -normalize(ray.dir);  // degenerate: face the ray
  const bool entering = dot(ng, ray.dir) < 0;
  if (!entering) ng = -ng;
  Vec3f ns = ng;
  if (const auto corners = scene.normals(t)) {
    const auto& n = *corners;
    const float w = 1.0f - hit.u - hit.v;
    const Vec3f interpolated = n[0] * w + n[1] * hit.u + n[2] * hit.v;
    if (max_abs(interpolated) > 0 && max_abs(interpolated) <= kMaxFinite) {
      ns = normalize_any(interpolated);
      if (dot(ns, ng) < 0) ns = -ns;
    }
  }
  float u = 0, v = 0;
  if (const auto corners = scene.uv(t)) {
    const auto& uv = *corners;
    const float w = 1.0f - hit.u - hit.v;
    u = uv[0][0] * w + uv[1][0] * hit.u + uv[2][0] * hit.v;
    v = uv[0][1] * w + uv[1][1] * hit.u + uv[2][1] * hit.v;
  }
  Vec3f color{1, 1, 1};
  if (const auto corners = scene.colors(t)) {
    const auto& c = *corners;
    color = c[0] * (1.0f - hit.u - hit.v) + c[1] * hit.u + c[2] * hit.v;
  }
  s.p = v0 + e1 * hit.u + e2 * hit.v;
  s.ng = ng;
  s.ns = ns;
  s.entering = entering;
  s.u = u;
  s.v = v;
  s.color = color;
  s.material = scene.triangle_material[t];
}

Vec3f diffuse_albedo(const Scene& scene, const SurfacePoint& s) {
  const Material& m = scene.materials[s.material];
  const int32_t tex = scene.material_texture[s.material];
  if (tex < 0) return m.Kd * s.color;
  const Texture& img = scene.textures[tex];
  const int width = img.width(), height = img.height();
  // OBJ texture space has v up; image row 0 is the top.
  const float u = repeat(s.u * m.map_Kd_scale[0] + m.map_Kd_offset[0]);
  const float v = repeat(s.v * m.map_Kd_scale[1] + m.map_Kd_offset[1]);
  const float fx = u * float(width) - 0.5f;
  const float fy = (1.0f - v) * float(height) - 0.5f;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const float ax = fx - float(x0), ay = fy - float(y0);
  auto texel = [&](int x, int y) {
    x = ((x % width) + width) % width;
    y = ((y % height) + height) % height;
    return img.texel(x, y);
  };
  const Vec3f top = texel(x0, y0) * (1 - ax) + texel(x0 + 1, y0) * ax;
  const Vec3f bottom = texel(x0, y0 + 1) * (1 - ax) + texel(x0 + 1, y0 + 1) * ax;
  return m.Kd * (top * (1 - ay) + bottom * ay) * s.color;
}

}  // namespace rayvec
