// rays/pinhole_camera: the framing guarantee (the whole box inside the view, the eye outside its
// bounding sphere) and the look-at frame, in float and double; and the three cameras built on them
// (render's CameraRays, the bench's frame_mesh, a bare OBJ's frame_bounding_box) keep every corner
// of the box inside their image.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "bench/ray_sets.h"
#include "geometry/triangle_mesh.h"
#include "rays/pinhole_camera.h"
#include "render/camera_rays.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

BBox random_box(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-10, 10), e(0.01f, 5);
  const Vec3f lo{u(rng), u(rng), u(rng)};
  return BBox{lo, lo + Vec3f{e(rng), e(rng), e(rng)}};
}

Vec3f corner(const BBox& b, int k) {
  return {k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z};
}

// Where a point lands on the image plane at distance 1 along forward: (u, v), as direction() takes.
template <typename T>
std::pair<T, T> project(const PinholeFrame<T>& f, Vec3<T> eye, Vec3<T> p) {
  const Vec3<T> d = p - eye;
  const T z = dot(d, f.forward);
  return {dot(d, f.right) / z, dot(d, f.up) / z};
}

template <typename T>
void check_frame_box(int seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> dir(-1, 1), angle(T(5 * kDeg), T(80 * kDeg)), margin(1, 1.5);
  for (int i = 0; i < 500; ++i) {
    const BBox box = random_box(rng);
    const Vec3<T> toward{dir(rng), dir(rng), dir(rng)};
    if (!(length(toward) > T(0.1))) continue;
    const T half = angle(rng), m = margin(rng);
    const BoxFraming<T> f = frame_box(box, toward, half, m);
    EXPECT_GT(length(f.eye - f.center), f.radius);
    const T cone = std::asin(std::sin(half) / m);
    for (int k = 0; k < 8; ++k) {
      const Vec3<T> c(corner(box, k));
      EXPECT_LE(length(c - f.center), f.radius * T(1.0001));
      const T cosine = dot(normalize(c - f.eye), normalize(f.center - f.eye));
      EXPECT_GE(cosine, std::cos(cone) - T(1e-5)) << "corner " << k << " outside the cone";
    }
  }
}

TEST(FrameBox, WholeBoxInsideTheConeFloat) { check_frame_box<float>(1); }
TEST(FrameBox, WholeBoxInsideTheConeDouble) { check_frame_box<double>(2); }

TEST(FrameBox, PointBoxGivesAnEyeApartFromTheCentre) {
  const BBox point{Vec3f{1, 2, 3}, Vec3f{1, 2, 3}};
  const BoxFraming<double> f = frame_box(point, Vec3d{0, 0, 1}, 0.5, 1.0);
  EXPECT_EQ(f.center, (Vec3d{1, 2, 3}));
  EXPECT_GT(f.distance, 0.0);
  EXPECT_TRUE(is_finite(f.eye));
}

TEST(NarrowerHalfFov, PortraitUsesTheHorizontalHalfAngle) {
  EXPECT_EQ(narrower_half_fov(0.4, 1.5), 0.4);
  EXPECT_EQ(narrower_half_fov(0.4, 1.0), 0.4);
  EXPECT_NEAR(std::tan(narrower_half_fov(0.4, 0.5)), std::tan(0.4) * 0.5, 1e-15);
}

TEST(LookAtFrame, OrthonormalAndRightHanded) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 200; ++i) {
    const Vec3d eye{u(rng), u(rng), u(rng)}, target{u(rng), u(rng), u(rng)}, hint{u(rng), u(rng), u(rng)};
    const PinholeFrame<double> f = look_at_frame(eye, target, hint);
    EXPECT_NEAR(length(f.forward), 1, 1e-12);
    EXPECT_NEAR(length(f.right), 1, 1e-12);
    EXPECT_NEAR(length(f.up), 1, 1e-12);
    EXPECT_NEAR(dot(f.forward, f.right), 0, 1e-12);
    EXPECT_NEAR(dot(f.forward, f.up), 0, 1e-12);
    EXPECT_NEAR(dot(f.right, f.up), 0, 1e-12);
    EXPECT_GT(dot(f.up, hint), -1e-12);  // up leans toward the hint
    EXPECT_NEAR(length(f.direction(0, 0) - f.forward), 0, 1e-12);
    EXPECT_NEAR(length(cross(f.right, f.up) - (-f.forward)), 0, 1e-12);  // right × up = backward
  }
}

// A bare OBJ's camera sees every vertex of the model, landscape, square and portrait.
TEST(FrameBoundingBox, EveryCornerInsideTheImage) {
  std::mt19937 rng(4);
  for (auto [w, h] : {std::pair{640, 480}, {300, 300}, {100, 400}}) {
    Scene scene;
    scene.camera.width = w;
    scene.camera.height = h;
    const BBox box = random_box(rng);
    scene.add_triangle(box.lo, box.hi, Vec3f{box.lo.x, box.hi.y, box.lo.z}, scene.add_material({}));
    frame_bounding_box(scene);
    const Camera& c = scene.camera;
    const PinholeFrame<float> f = look_at_frame(c.eye, c.look_at, c.up);
    const float tan_half = std::tan(0.5f * c.fov_y * float(kDeg));
    for (const Vec3f& p : scene.mesh.positions) {
      const auto [u, v] = project(f, c.eye, p);
      EXPECT_LE(std::abs(u), tan_half * float(w) / float(h)) << w << "x" << h;
      EXPECT_LE(std::abs(v), tan_half) << w << "x" << h;
    }
    // CameraRays' ray through the image centre is the frame's forward axis.
    const Ray r = CameraRays(c).ray(0.5f * float(w), 0.5f * float(h));
    EXPECT_NEAR(length(r.dir - f.forward), 0, 1e-6f);
  }
}

// The bench's camera sees every corner of the mesh's box (its 45° field is vertical; square image).
TEST(FrameMesh, EveryCornerInsideTheImage) {
  std::mt19937 rng(5);
  for (int i = 0; i < 20; ++i) {
    const BBox box = random_box(rng);
    TriangleMesh mesh;
    mesh.add_triangle(box.lo, box.hi, Vec3f{box.hi.x, box.lo.y, box.lo.z});
    const BenchCamera cam = frame_mesh(mesh, 64, 64);
    for (int k = 0; k < 8; ++k) {
      const auto [u, v] = project(cam.frame, cam.eye, Vec3d(corner(box, k)));
      EXPECT_LE(std::abs(u), cam.th);
      EXPECT_LE(std::abs(v), cam.th);
    }
  }
}

}  // namespace
}  // namespace rayvec
