// Hard-case families (see hard_cases.h). Geometry is built in double and rounded to float once, so
// shared vertices are bit-identical in every triangle that uses them (closed meshes). Rays are
// "aimed" at a point p: the origin is rounded to float first and the direction is p minus that
// float origin, rounded — the ray passes within rounding of p, which is where intersectors differ.
#include "accuracy/hard_cases.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>

namespace rayvec {

namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

Vec3d in_ball(Rng& rng, double radius) {
  for (;;) {
    const Vec3d p{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
    if (dot(p, p) <= 1.0 && dot(p, p) > 1e-6) return p * radius;
  }
}
Vec3d unit(Rng& rng) { return normalize(in_ball(rng, 1.0)); }

// A rotation from a random unit quaternion (identity for seed 0).
struct Rotation {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  explicit Rotation(uint64_t seed) {
    if (seed == 0) return;
    Rng rng(seed);
    double q[4];
    double n = 0;
    do {
      for (double& x : q) x = uniform(rng, -1, 1);
      n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    } while (n > 1 || n < 1e-3);
    for (double& x : q) x /= std::sqrt(n);
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = r[i][j];
  }
  Vec3d operator()(Vec3d v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
};

Vec3f to_float(Vec3d v) { return Vec3f(v); }
Vec3d to_double(Vec3f v) { return Vec3d(v); }

// A ray from `org` (rounded to float) aimed at p.
Ray aimed(Vec3d org, Vec3d p) {
  const Vec3f o = to_float(org);
  return Ray{o, to_float(p - to_double(o))};
}

// Positions from unit-sphere directions, placed and rotated, rounded to float once.
TriangleMesh place(const std::vector<Vec3d>& unit_positions,
                   const std::vector<std::array<uint32_t, 3>>& triangles, Vec3d centre, double radius,
                   uint64_t rotate_seed) {
  const Rotation rot(rotate_seed);
  TriangleMesh m;
  for (const Vec3d& u : unit_positions) m.positions.push_back(to_float(centre + rot(u) * radius));
  m.triangles = triangles;
  return m;
}

void append(TriangleMesh& into, const TriangleMesh& more) {
  const auto base = uint32_t(into.positions.size());
  into.positions.insert(into.positions.end(), more.positions.begin(), more.positions.end());
  for (auto t : more.triangles) into.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// Vertices and edge midpoints of a closed mesh (the points where neighbours meet).
std::vector<Vec3d> shared_points(const TriangleMesh& m, std::size_t first_triangle = 0) {
  std::vector<Vec3d> out;
  std::set<uint32_t> verts;
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (std::size_t t = first_triangle; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      verts.insert(a);
      edges.insert({a < b ? a : b, a < b ? b : a});
    }
  for (uint32_t v : verts) out.push_back(to_double(m.positions[v]));
  for (auto [a, b] : edges) out.push_back((to_double(m.positions[a]) + to_double(m.positions[b])) * 0.5);
  return out;
}

// Rays through shared vertices and edge midpoints of a convex closed mesh around `centre`: from
// outside, along the line from the centre through p (jittered a little, still entering the
// interior), and from inside points near the centre. Every such ray crosses the surface.
void add_targeted_rays(HardCaseFamily& f, const std::vector<Vec3d>& targets, Vec3d centre,
                       double inner_radius, int n, Rng& rng) {
  std::uniform_int_distribution<std::size_t> pick(0, targets.size() - 1);
  for (int k = 0; k < n; ++k) {
    const Vec3d p = targets[pick(rng)];
    if (k % 2 == 0) {
      const Vec3d out = p - centre;
      const Vec3d org = p + (out + in_ball(rng, 0.1 * length(out))) * uniform(rng, 0.5, 3.0);
      f.rays.push_back(aimed(org, p));
    } else {
      f.rays.push_back(aimed(centre + in_ball(rng, inner_radius), p));
    }
  }
}

Vec3d random_centre(Rng& rng, double extent) {
  return {uniform(rng, -extent, extent), uniform(rng, -extent, extent), uniform(rng, -extent, extent)};
}

HardCaseFamily closed_family(std::string name, std::string description, const TriangleMesh& mesh,
                             Vec3d centre, double radius, int n, Rng& rng) {
  HardCaseFamily f{std::move(name), std::move(description), mesh, {}, true, false};
  add_targeted_rays(f, shared_points(mesh), centre, 0.3 * radius, n, rng);
  return f;
}

// A random point of triangle t, or of one of its edges (every third), in double.
Vec3d point_on(const TriangleMesh& m, std::size_t t, Rng& rng, int k) {
  const Vec3d a = to_double(m.vertex(t, 0)), b = to_double(m.vertex(t, 1)), c = to_double(m.vertex(t, 2));
  double u = uniform(rng, 0, 1), v = uniform(rng, 0, 1);
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  if (k % 3 == 1) v = 0;      // on the edge a–b
  if (k % 3 == 2) v = 1 - u;  // on the edge b–c
  return a + (b - a) * u + (c - a) * v;
}

// Rays from random far origins aimed at random points (and edge points) of random triangles.
void add_rays_at_triangles(HardCaseFamily& f, int n, double origin_distance, Rng& rng) {
  std::uniform_int_distribution<std::size_t> pick(0, f.mesh.size() - 1);
  for (int k = 0; k < n; ++k) {
    const std::size_t t = pick(rng);
    const Vec3d p = point_on(f.mesh, t, rng, k);
    f.rays.push_back(aimed(p + unit(rng) * origin_distance, p));
  }
}

}  // namespace

// grid_box({0, 0, 0}, 1, 4) puts the vertices on a 0.5 grid, exactly representable, so axis-parallel
// rays can pass exactly through vertices and edges.
TriangleMesh grid_box(Vec3d centre, double half, int n) {
  TriangleMesh m;
  std::map<std::array<int, 3>, uint32_t> index;
  auto vertex = [&](std::array<int, 3> g) {
    auto [it, fresh] = index.try_emplace(g, uint32_t(m.positions.size()));
    if (fresh) {
      const auto coord = [&](int a) { return centre[a] + half * (-1.0 + 2.0 * g[std::size_t(a)] / n); };
      m.positions.push_back(Vec3f(Vec3d{coord(0), coord(1), coord(2)}));
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            std::array<int, 3> g{};
            g[axis] = side;
            g[(axis + 1) % 3] = a;
            g[(axis + 2) % 3] = b;
            return vertex(g);
          };
          const uint32_t p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
          if ((i + j) % 2 == 0) {
            m.triangles.push_back({p00, p10, p11});
            m.triangles.push_back({p00, p11, p01});
          } else {
            m.triangles.push_back({p00, p10, p01});
            m.triangles.push_back({p10, p11, p01});
          }
        }
  return m;
}

TriangleMesh make_octahedron(Vec3d centre, double radius, uint64_t rotate_seed) {
  const std::vector<Vec3d> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::vector<std::array<uint32_t, 3>> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return place(p, t, centre, radius, rotate_seed);
}

TriangleMesh make_icosphere(Vec3d centre, double radius, int subdivisions, uint64_t rotate_seed) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3d> p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3d& v : p) v = normalize(v);
  std::vector<std::array<uint32_t, 3>> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::make_pair(a < b ? a : b, a < b ? b : a);
      auto [it, fresh] = mid.try_emplace(key, uint32_t(p.size()));
      if (fresh) p.push_back(normalize(p[a] + p[b]));
      return it->second;
    };
    std::vector<std::array<uint32_t, 3>> next;
    for (auto [a, b, c] : t) {
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    t = std::move(next);
  }
  return place(p, t, centre, radius, rotate_seed);
}

std::vector<HardCaseFamily> hard_case_families(uint64_t seed, int scale) {
  Rng rng(seed);
  const int n = 300 * (scale < 1 ? 1 : scale);
  std::vector<HardCaseFamily> out;

  {  // octahedra: the sharpest vertices (four faces meet at 90°)
    const Vec3d c = random_centre(rng, 2);
    const double r = uniform(rng, 0.5, 3);
    out.push_back(closed_family("octahedron_vertices_edges",
                                "rays through vertices and edge midpoints of a rotated octahedron, "
                                "from outside and inside",
                                make_octahedron(c, r, rng()), c, r, n, rng));
  }
  {
    const Vec3d c = random_centre(rng, 2);
    const double r = std::exp(uniform(rng, std::log(0.1), std::log(20.0)));
    out.push_back(closed_family("sphere_vertices_edges",
                                "rays through vertices and edge midpoints of a 320-triangle sphere of "
                                "random radius, from outside and inside",
                                make_icosphere(c, r, 2, rng()), c, r, n, rng));
  }
  {
    const Vec3d c = random_centre(rng, 2);
    const double r = uniform(rng, 0.2, 5);
    HardCaseFamily f{"inside_points",
                     "rays from random points inside a closed sphere, random directions",
                     make_icosphere(c, r, 2, rng()),
                     {},
                     true,
                     false};
    for (int k = 0; k < n; ++k)
      f.rays.push_back(Ray{to_float(c + in_ball(rng, 0.5 * r)), to_float(unit(rng))});
    out.push_back(std::move(f));
  }
  {  // two triangles sharing the diagonal a–c of a rotated quad
    const Vec3d c = random_centre(rng, 1);
    const std::vector<Vec3d> quad = {{-1, -0.8, 0}, {1.1, -1, 0.05}, {0.9, 1.2, -0.03}, {-1.05, 0.95, 0}};
    HardCaseFamily f{"quad_diagonal",
                     "rays at points of the shared diagonal of a rotated quad",
                     place(quad, {{0, 1, 2}, {0, 2, 3}}, c, 1.0, rng()),
                     {},
                     true,
                     false};
    const Vec3d a = to_double(f.mesh.positions[0]), d = to_double(f.mesh.positions[2]);
    const Vec3d normal = normalize(cross(d - a, to_double(f.mesh.positions[1]) - a));
    for (int k = 0; k < 4 * n; ++k) {
      const Vec3d p = a + (d - a) * uniform(rng, 0.02, 0.98);
      const Vec3d side = normal * (k % 2 ? 1.0 : -1.0) + in_ball(rng, 0.9);
      f.rays.push_back(aimed(p + side * uniform(rng, 0.5, 4), p));
    }
    out.push_back(std::move(f));
  }
  const Vec3d far{148376, 1234, -223423};
  {
    const Vec3d c = far + random_centre(rng, 10);
    const double r = uniform(rng, 5, 50);
    out.push_back(closed_family("far_octahedron",
                                "the octahedron family translated to (148376, 1234, -223423)",
                                make_octahedron(c, r, rng()), c, r, n, rng));
  }
  {
    const Vec3d c = far + random_centre(rng, 10);
    const double r = uniform(rng, 20, 100);
    out.push_back(closed_family("far_sphere", "the sphere family translated to (148376, 1234, -223423)",
                                make_icosphere(c, r, 2, rng()), c, r, n, rng));
  }
  {  // closed spheres of radius 1e-4 and 1e-6 (edges ~6e-5 and ~6e-7)
    const Vec3d c1{0.01, 0.02, -0.03}, c2{-1e-3, 2e-3, 1e-3};
    TriangleMesh mesh = make_icosphere(c1, 1e-4, 1, rng());
    const std::size_t first2 = mesh.size();
    append(mesh, make_icosphere(c2, 1e-6, 1, rng()));
    HardCaseFamily f{
        "tiny_closed", "rays through vertices and edges of closed spheres of radius 1e-4 and 1e-6",
        mesh,          {},
        true,          false};
    TriangleMesh m1 = mesh, m2 = mesh;
    m1.triangles.resize(first2);
    add_targeted_rays(f, shared_points(m1), c1, 0.3e-4, n / 2, rng);
    add_targeted_rays(f, shared_points(mesh, first2), c2, 0.3e-6, n - n / 2, rng);
    out.push_back(std::move(f));
  }
  {  // open tiny triangles and huge ones, long thin slivers
    HardCaseFamily f{"tiny_huge_slivers",
                     "single triangles with edges 1e-4, 1e-6 and 1e5, and slivers 1 x 1e-5, rays at "
                     "interior and edge points",
                     {},
                     {},
                     false,
                     false};
    for (int k = 0; k < 60; ++k) {
      const Vec3d c = random_centre(rng, 1);
      const double size = (k % 4 == 0) ? 1e-4 : (k % 4 == 1) ? 1e-6 : (k % 4 == 2) ? 1e5 : 1.0;
      const Vec3d u = unit(rng), w = normalize(cross(u, unit(rng)));
      const double width = (k % 4 == 3) ? 1e-5 : size;
      f.mesh.add_triangle(to_float(c), to_float(c + u * size), to_float(c + u * (0.5 * size) + w * width));
    }
    add_rays_at_triangles(f, n, 3.0, rng);
    out.push_back(std::move(f));
  }
  {  // rays in or nearly in a triangle's plane
    HardCaseFamily f{"grazing", "rays in or within 1e-7..1e-3 of a triangle's plane", {}, {}, false, false};
    for (int k = 0; k < 40; ++k) {
      const Vec3d c = random_centre(rng, 3);
      f.mesh.add_triangle(to_float(c + unit(rng)), to_float(c + unit(rng)), to_float(c + unit(rng)));
    }
    std::uniform_int_distribution<std::size_t> pick(0, f.mesh.size() - 1);
    const double tilt[] = {0, 1e-7, 1e-5, 1e-3};
    for (int k = 0; k < n; ++k) {
      const std::size_t t = pick(rng);
      const Vec3d a = to_double(f.mesh.vertex(t, 0)), b = to_double(f.mesh.vertex(t, 1)),
                  c = to_double(f.mesh.vertex(t, 2));
      const Vec3d nrm = normalize(cross(b - a, c - a));
      const Vec3d p = point_on(f.mesh, t, rng, k);
      Vec3d in_plane = unit(rng);
      in_plane = normalize(in_plane - nrm * dot(in_plane, nrm));
      const Vec3d org = p + in_plane * 2.0 + nrm * (tilt[k % 4] * (k % 8 < 4 ? 1.0 : -1.0) * 2.0);
      f.rays.push_back(aimed(org, p));
    }
    out.push_back(std::move(f));
  }
  {  // axis-parallel rays and zero direction components against a grid box
    HardCaseFamily f{"axis_parallel_grid",
                     "axis-parallel rays and rays with zero direction components through grid "
                     "vertices, edges and diagonals of a closed box",
                     grid_box({0, 0, 0}, 1.0, 4),
                     {},
                     true,
                     false};
    std::uniform_int_distribution<int> grid(1, 7), axis_pick(0, 2);
    for (int k = 0; k < n; ++k) {
      const int axis = axis_pick(rng);
      const double side = (k % 2) ? 1.0 : -1.0;
      Vec3d p;  // a point of the face's interior on the 0.25 grid
      p[axis] = side;
      p[(axis + 1) % 3] = -1 + 0.25 * grid(rng);
      p[(axis + 2) % 3] = -1 + 0.25 * grid(rng);
      Vec3d org = p;
      org[axis] = side * 3;
      if (k % 4 >= 2) org[(axis + 1) % 3] += 0.5 * side;  // one zero component, not two
      if (k % 8 == 7) {                                   // from inside, one zero component
        org = {uniform(rng, -0.7, 0.7), uniform(rng, -0.7, 0.7), uniform(rng, -0.7, 0.7)};
        Vec3d d = unit(rng);
        d[axis] = 0;
        f.rays.push_back(Ray{to_float(org), to_float(d)});
        continue;
      }
      f.rays.push_back(aimed(org, p));
    }
    out.push_back(std::move(f));
  }
  {  // zero-area triangles
    HardCaseFamily f{"degenerate", "collinear triangles, repeated vertices and points", {}, {}, false, true};
    for (int k = 0; k < 30; ++k) {
      Vec3d g = random_centre(rng, 2);  // on a 1/8 grid: a + d and a + 2d stay exact (collinear)
      g = {std::round(g.x * 8) / 8, std::round(g.y * 8) / 8, std::round(g.z * 8) / 8};
      const Vec3f a = to_float(g);
      const Vec3f d{0.25f * float(k % 5 - 2), 0.5f, 0.125f * float(k % 3)};
      if (k % 3 == 0)
        f.mesh.add_triangle(a, {a.x + d.x, a.y + d.y, a.z + d.z},
                            {a.x + 2 * d.x, a.y + 2 * d.y, a.z + 2 * d.z});
      if (k % 3 == 1) f.mesh.add_triangle(a, a, {a.x + d.x, a.y + d.y, a.z + d.z});
      if (k % 3 == 2) f.mesh.add_triangle(a, a, a);
    }
    std::uniform_int_distribution<std::size_t> pick(0, f.mesh.size() - 1);
    for (int k = 0; k < n; ++k) {
      const std::size_t t = pick(rng);
      const Vec3d p = (to_double(f.mesh.vertex(t, k % 3)) + to_double(f.mesh.vertex(t, (k + 1) % 3))) * 0.5;
      f.rays.push_back(aimed(p + unit(rng) * 2.0, p));
    }
    out.push_back(std::move(f));
  }
  {  // NaN and Inf in rays and vertices
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInf;
    HardCaseFamily f{"non_finite", "NaN and Inf in ray fields and in triangle vertices", {}, {}, false,
                     false};
    for (int k = 0; k < 16; ++k) {
      const Vec3f a{float(k % 4) * 2, float(k / 4) * 2, 5}, b{a.x + 1.5f, a.y, 5.2f},
          c{a.x, a.y + 1.5f, 4.9f};
      f.mesh.add_triangle(a, b, c);
      const Vec3f bad[] = {{nan, a.y, 5}, {a.x, inf, 5}, {a.x + 1, a.y + 1, -inf}, {nan, nan, nan}};
      f.mesh.add_triangle(a, b, bad[k % 4]);  // overlaps the good triangle
    }
    for (int k = 0; k < n; ++k) {
      const int t = 2 * (k % 16);
      const Vec3d p =
          (to_double(f.mesh.vertex(t, 0)) + to_double(f.mesh.vertex(t, 1)) + to_double(f.mesh.vertex(t, 2))) /
          3.0;
      Ray r = aimed(p + Vec3d{uniform(rng, -1, 1), uniform(rng, -1, 1), -4}, p);
      switch (k % 8) {
        case 1: r.org.x = nan; break;
        case 2: r.dir.y = nan; break;
        case 3: r.dir.z = inf; break;
        case 4: r.org.z = -inf; break;
        case 5: r.tmin = nan; break;
        case 6: r.tmax = nan; break;
        default: break;  // finite rays: must hit the good triangle
      }
      f.rays.push_back(r);
    }
    out.push_back(std::move(f));
  }
  return out;
}

HardCaseFamily random_control_family(uint64_t seed, int scale) {
  Rng rng(seed);
  HardCaseFamily f{
      "random_control", "200 random triangles, random rays (rounding rarely matters)", {}, {}, false, false};
  for (int k = 0; k < 200; ++k) {
    const Vec3d c = random_centre(rng, 1);
    f.mesh.add_triangle(to_float(c + in_ball(rng, 0.3)), to_float(c + in_ball(rng, 0.3)),
                        to_float(c + in_ball(rng, 0.3)));
  }
  const int n = 300 * (scale < 1 ? 1 : scale);
  for (int k = 0; k < n; ++k) {
    const Vec3d target = random_centre(rng, 0.5);
    f.rays.push_back(aimed(unit(rng) * 3.0, target));
  }
  return f;
}

}  // namespace rayvec
