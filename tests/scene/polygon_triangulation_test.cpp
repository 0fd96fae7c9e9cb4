// triangulate_polygon and quad_splits_at_0_2: n − 2 triangles in the polygon's winding that cover
// a simple polygon exactly once (checked by sampling points against the even-odd rule), for
// concave shapes, holes joined by a bridge, collinear runs, tilted planes and either orientation;
// n − 2 triangles over the corners for polygons that cross themselves or have no plane.
#include "scene/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace rayvec {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;
using Poly2 = std::vector<std::pair<double, double>>;

Triangles triangulate(const std::vector<Vec3f>& p) {
  Triangles t;
  triangulate_polygon(p, t);
  return t;
}

// A 2D polygon placed in 3D: in the xy plane, or rotated about a slanted axis and moved away from
// the origin, so no axis is special.
std::vector<Vec3f> place(const Poly2& poly, bool tilted) {
  std::vector<Vec3f> p;
  for (const auto& [x, y] : poly) {
    if (!tilted) {
      p.push_back({float(x), float(y), 0.0f});
      continue;
    }
    // an orthonormal frame a, b in a plane with normal (1,2,3)/|..|
    const Vec3d a = normalize(Vec3d{2, -1, 0}), n = normalize(Vec3d{1, 2, 3}), b = cross(n, a);
    const Vec3d q = Vec3d{5, -3, 7} + a * x + b * y;
    p.push_back(Vec3f(q));
  }
  return p;
}

bool inside_even_odd(const Poly2& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto [xi, yi] = poly[i];
    const auto [xj, yj] = poly[j];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

double distance_to_segment(double x, double y, std::pair<double, double> a, std::pair<double, double> b) {
  const double dx = b.first - a.first, dy = b.second - a.second;
  const double len2 = dx * dx + dy * dy;
  double s = len2 > 0 ? ((x - a.first) * dx + (y - a.second) * dy) / len2 : 0;
  s = std::clamp(s, 0.0, 1.0);
  return std::hypot(x - a.first - s * dx, y - a.second - s * dy);
}

double cross2(std::pair<double, double> a, std::pair<double, double> b, double x, double y) {
  return (b.first - a.first) * (y - a.second) - (b.second - a.second) * (x - a.first);
}

double signed_area(const Poly2& poly) {
  double s = 0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    s += poly[j].first * poly[i].second - poly[i].first * poly[j].second;
  return 0.5 * s;
}

// n − 2 triangles, none wound against the polygon, and every sample point away from the edges
// covered by exactly as many triangles as the even-odd rule puts it inside the polygon (1 or 0).
void expect_exact_cover(const Poly2& poly, const std::string& name) {
  for (const bool tilted : {false, true}) {
    const Triangles t = triangulate(place(poly, tilted));
    ASSERT_EQ(t.size(), poly.size() - 2) << name;
    const double sign = signed_area(poly) > 0 ? 1 : -1;
    double total = 0;
    for (const auto& tri : t) {
      for (uint32_t c : tri) ASSERT_LT(c, poly.size()) << name;
      EXPECT_TRUE(tri[0] < tri[1] || tri[1] < tri[2] || tri[2] < tri[0]) << name;
      const double a2 = sign * cross2(poly[tri[0]], poly[tri[1]], poly[tri[2]].first, poly[tri[2]].second);
      EXPECT_GE(a2, -1e-9) << name << ": a triangle wound against the polygon";
      total += 0.5 * a2;
    }
    EXPECT_NEAR(total, std::fabs(signed_area(poly)), 1e-6 * std::fabs(signed_area(poly))) << name;
    if (tilted) continue;  // coverage in the polygon's own coordinates
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& [x, y] : poly) {
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    const int steps = 97;
    int checked = 0;
    for (int i = 0; i <= steps; ++i) {
      for (int j = 0; j <= steps; ++j) {
        const double x = x0 + (x1 - x0) * (i + 0.37) / (steps + 1),
                     y = y0 + (y1 - y0) * (j + 0.61) / (steps + 1);
        double near_edge = 1e300;
        for (std::size_t k = 0, l = poly.size() - 1; k < poly.size(); l = k++)
          near_edge = std::min(near_edge, distance_to_segment(x, y, poly[l], poly[k]));
        if (near_edge < 1e-6 * (x1 - x0 + y1 - y0)) continue;
        int covers = 0;
        for (const auto& tri : t) {
          const double s0 = sign * cross2(poly[tri[0]], poly[tri[1]], x, y);
          const double s1 = sign * cross2(poly[tri[1]], poly[tri[2]], x, y);
          const double s2 = sign * cross2(poly[tri[2]], poly[tri[0]], x, y);
          covers += s0 > 0 && s1 > 0 && s2 > 0;
        }
        ASSERT_EQ(covers, inside_even_odd(poly, x, y) ? 1 : 0) << name << " at " << x << "," << y;
        ++checked;
      }
    }
    EXPECT_GT(checked, steps * steps / 2) << name;
  }
}

Poly2 reversed(Poly2 p) {
  std::reverse(p.begin(), p.end());
  return p;
}

TEST(PolygonTriangulation, ConcaveShapesAreCoveredExactlyOnce) {
  const Poly2 l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Poly2 star, comb = {{0, 0}, {10, 0}}, spiral;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 == 0 ? 2 : 0.8, a = k * M_PI / 5;
    star.push_back({r * std::cos(a), r * std::sin(a)});
  }
  for (int k = 5; k > 0; --k) {  // five teeth, from the right
    comb.push_back({2.0 * k, 3});
    comb.push_back({2.0 * k - 1, 3});
    comb.push_back({2.0 * k - 1, 1});
    comb.push_back({2.0 * k - 2, 1});
  }
  comb.back() = {0, 3};
  for (int i = 0; i <= 60; ++i) {
    const double a = i * 4 * M_PI / 60, r = 1 + i / 60.0 * 3;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  for (int i = 60; i >= 0; --i) {
    const double a = i * 4 * M_PI / 60, r = 1.5 + i / 60.0 * 3;
    spiral.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const Poly2 collinear = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {0, 1}};
  for (const auto& [name, poly] : {std::pair<std::string, Poly2>{"L", l_shape},
                                   {"star", star},
                                   {"comb", comb},
                                   {"spiral", spiral},
                                   {"collinear runs", collinear}}) {
    expect_exact_cover(poly, name);
    expect_exact_cover(reversed(poly), name + " reversed");
  }
}

TEST(PolygonTriangulation, AHoleJoinedByABridgeStaysOpen) {
  // a square with a square hole, the hole reached along a doubled edge (how exporters write
  // polygons with holes: assimp's concave_polygon.obj is a ring made so)
  const Poly2 keyhole = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
  expect_exact_cover(keyhole, "keyhole");
  expect_exact_cover(reversed(keyhole), "keyhole reversed");
  Poly2 ring;  // 32-gon outside, 24-gon hole, bridged at angle 0
  for (int k = 0; k <= 32; ++k) ring.push_back({3 * std::cos(k * M_PI / 16), 3 * std::sin(k * M_PI / 16)});
  for (int k = 24; k >= 0; --k) ring.push_back({2 * std::cos(k * M_PI / 12), 2 * std::sin(k * M_PI / 12)});
  expect_exact_cover(ring, "ring");
}

// Simple polygons from random points: the crossing edges of a random order undone by reversals
// until none is left (2-opt), which leaves a simple, mostly concave polygon.
Poly2 random_simple_polygon(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> coord(0, 1);
  Poly2 p(static_cast<std::size_t>(n));
  for (auto& [x, y] : p) x = coord(rng), y = coord(rng);
  const auto crosses = [](auto a, auto b, auto c, auto d) {
    const auto o = [](auto p0, auto p1, auto p2) {
      return (p1.first - p0.first) * (p2.second - p0.second) -
             (p1.second - p0.second) * (p2.first - p0.first);
    };
    return o(a, b, c) * o(a, b, d) < 0 && o(c, d, a) * o(c, d, b) < 0;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        if (crosses(p[i], p[i + 1], p[j], p[(j + 1) % n])) {
          std::reverse(p.begin() + i + 1, p.begin() + j + 1);
          changed = true;
        }
      }
  }
  return p;
}

TEST(PolygonTriangulation, RandomSimplePolygonsAreCoveredExactlyOnce) {
  std::mt19937 rng(20261205);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 5 + trial % 30;
    expect_exact_cover(random_simple_polygon(rng, n), "random polygon " + std::to_string(trial));
  }
}

TEST(PolygonTriangulation, PolygonsWithoutAPlaneOrCrossingThemselvesKeepEveryCorner) {
  const std::vector<std::vector<Vec3f>> odd = {
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},             // on a line
      {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},             // one point
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},  // a triangle twice
      {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}, {1, 3, 0}},             // crosses itself
      {{1, 0, 0},
       {-0.81f, 0.59f, 0},
       {0.31f, -0.95f, 0},
       {0.31f, 0.95f, 0},
       {-0.81f, -0.59f, 0}},                                                          // pentagram
      {{0, 0, 0}, {1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {0.5f, 0.5f, 3}, {-1, 0.5f, 0}}};  // far from planar
  for (std::size_t i = 0; i < odd.size(); ++i) {
    const Triangles t = triangulate(odd[i]);
    ASSERT_EQ(t.size(), odd[i].size() - 2) << "polygon " << i;
    std::vector<int> used(odd[i].size());
    for (const auto& tri : t)
      for (uint32_t c : tri) {
        ASSERT_LT(c, odd[i].size());
        used[c] = 1;
      }
    for (std::size_t c = 0; c < used.size(); ++c) EXPECT_TRUE(used[c]) << "polygon " << i << " corner " << c;
    EXPECT_EQ(triangulate(odd[i]), t) << "polygon " << i << ": not deterministic";
  }
}

TEST(PolygonTriangulation, RandomCornerSoupsGiveEveryTriangle) {
  // corners in random order, some repeated, some on a coarse grid (collinear and coincident
  // runs), in 3D: whatever the polygon, n − 2 triangles of valid corners
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> grid(0, 3);
  std::uniform_real_distribution<float> coord(-1, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 5 + trial % 40;
    std::vector<Vec3f> p;
    for (int i = 0; i < n; ++i) {
      if (i > 0 && trial % 3 == 0 && grid(rng) == 0)
        p.push_back(p[std::uniform_int_distribution<std::size_t>(0, p.size() - 1)(rng)]);
      else if (trial % 3 == 1)
        p.push_back({float(grid(rng)), float(grid(rng)), 0});
      else
        p.push_back({coord(rng), coord(rng), trial % 2 ? coord(rng) * 0.1f : 0});
    }
    const Triangles t = triangulate(p);
    ASSERT_EQ(t.size(), p.size() - 2) << "trial " << trial;
    for (const auto& tri : t)
      for (uint32_t c : tri) ASSERT_LT(c, p.size()) << "trial " << trial;
  }
}

TEST(PolygonTriangulation, AConcaveQuadIsSplitFromItsReflexCorner) {
  // an arrowhead pointing to -x: corner 2 is reflex and the diagonal 1–3 (2 long) lies outside,
  // although it is shorter than 0–2 (5 long)
  const std::array<Vec3f, 4> dart = {{{0, 0, 0}, {10, -1, 0}, {5, 0, 0}, {10, 1, 0}}};
  EXPECT_TRUE(quad_splits_at_0_2(dart));
  // the same quad started one corner later: the reflex corner is now 1
  EXPECT_FALSE(quad_splits_at_0_2({dart[1], dart[2], dart[3], dart[0]}));
  // either orientation
  EXPECT_TRUE(quad_splits_at_0_2({dart[0], dart[3], dart[2], dart[1]}));
  // convex quads keep the shorter diagonal, 0–2 only when strictly shorter
  EXPECT_FALSE(quad_splits_at_0_2({{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {0, 1, 0}}}));  // 1–3 shorter
  EXPECT_TRUE(quad_splits_at_0_2({{{0, 0, 0}, {3, 0, 0}, {2, 1, 0}, {0, 1, 0}}}));   // 0–2 shorter
  EXPECT_FALSE(quad_splits_at_0_2({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}));  // a tie: 1–3
  const Triangles t = triangulate({dart.begin(), dart.end()});
  EXPECT_EQ(t, (Triangles{{0, 1, 2}, {0, 2, 3}}));
}

TEST(PolygonTriangulation, TheLargestFaceTheReadersAcceptGivesEveryTriangle) {
  // the largest face the OBJ readers accept (kMaxFaceCorners), concave all round: a star
  std::vector<Vec3f> star;
  for (int k = 0; k < 10000; ++k) {
    const double r = k % 2 == 0 ? 2 : 1.9, a = k * 2 * M_PI / 10000;
    star.push_back({float(r * std::cos(a)), float(r * std::sin(a)), 0});
  }
  const Triangles t = triangulate(star);
  EXPECT_EQ(t.size(), star.size() - 2);
}

}  // namespace
}  // namespace rayvec
