// The camera and light of a bare OBJ: any model in any orientation comes out framed and lit, the
// named views and explicit --eye/--look-at/--up/--fov work, and an empty picture is a warning.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "image/image_io.h"
#include "scene/default_view.h"
#include "test_support.h"

namespace rayvec {
namespace {

struct Coverage {
  double covered = 0;  // fraction of pixels that are not background (black)
  double mean = 0;     // mean RGB over the covered pixels
};

Coverage coverage(const std::string& exr) {
  const Image img = read_image(exr);
  std::size_t n = 0;
  double sum = 0;
  const std::size_t c = img.channels.size();
  for (std::size_t i = 0; i + 2 < img.pixels.size(); i += c) {
    const double v = img.pixels[i] + img.pixels[i + 1] + img.pixels[i + 2];
    if (v > 0) ++n, sum += v / 3;
  }
  const double total = double(img.width) * img.height;
  return {n / total, n ? sum / double(n) : 0.0};
}

// Renders `obj_text` as a bare OBJ at 48x36 into out.exr.
Coverage render_obj(const std::string& dir, const std::string& obj_text, const std::string& extra = "",
                    std::string* err = nullptr) {
  test::write_file(dir + "/m.obj", obj_text);
  const auto r =
      test::run_cli("render -q " + dir + "/m.obj --width 48 --height 36 -o " + dir + "/out.exr " + extra);
  EXPECT_EQ(r.status, 0) << r.err;
  if (err) *err = r.err;
  return coverage(dir + "/out.exr");
}

// A unit quad through the origin, rotated by (ax, ay, az) radians about x, then y, then z.
std::string quad(double ax, double ay, double az) {
  std::string text;
  for (auto [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    double x = u, y = v, z = 0;
    double t = y * std::cos(ax) - z * std::sin(ax);
    z = y * std::sin(ax) + z * std::cos(ax), y = t;
    t = x * std::cos(ay) + z * std::sin(ay);
    z = -x * std::sin(ay) + z * std::cos(ay), x = t;
    t = x * std::cos(az) - y * std::sin(az);
    y = x * std::sin(az) + y * std::cos(az), x = t;
    text += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  }
  return text + "f 1 2 3 4\n";
}

TEST(DefaultView, AQuadInEveryOrientationIsFramedAndLit) {
  const std::string dir = test::temp_dir("default_view_quads");
  const double h = std::acos(-1.0) / 2;
  // The XY, YZ and XZ planes (each both ways round), then a few arbitrary rotations.
  const double angles[][3] = {{0, 0, 0},  {0, h, 0},     {h, 0, 0},     {0, 2 * h, 0},  {0, -h, 0},
                              {-h, 0, 0}, {0.3, 0.7, 0}, {1.1, 0.2, 2}, {2.5, 1.3, 0.4}};
  for (const auto& a : angles) {
    SCOPED_TRACE(std::to_string(a[0]) + " " + std::to_string(a[1]) + " " + std::to_string(a[2]));
    const Coverage c = render_obj(dir, quad(a[0], a[1], a[2]));
    EXPECT_GT(c.covered, 0.25);  // the quad fills a good part of the frame, seen at an angle
    EXPECT_GT(c.mean, 0.1);      // and lit (Kd 0.8 without an MTL)
  }
}

TEST(DefaultView, AssimpModelsFillTheFrame) {
  const std::string models = "/usr/share/assimp/models/OBJ/";
  if (!std::filesystem::exists(models + "WusonOBJ.obj"))
    GTEST_SKIP() << "package assimp-testmodels is not installed";
  const std::string dir = test::temp_dir("default_view_assimp");
  // Coverage thresholds below what each model reaches (a spider's legs are thin).
  for (const auto& [name, least] : {std::pair<std::string, double>{"WusonOBJ.obj", 0.15},
                                    {"concave_polygon.obj", 0.04},  // a thin ring
                                    {"box.obj", 0.15},
                                    {"spider.obj", 0.06}}) {
    const auto r =
        test::run_cli("render -q " + models + name + " --width 48 --height 36 -o " + dir + "/out.exr");
    ASSERT_EQ(r.status, 0) << name << r.err;
    const Coverage c = coverage(dir + "/out.exr");
    EXPECT_GT(c.covered, least) << name;
    EXPECT_GT(c.mean, 0.02) << name;
  }
}

TEST(DefaultView, TheIsoViewPrefersTheSideThatShowsFrontFaces) {
  // A single-sided quad facing -z and an open box (floor and back wall facing +z, the opening at +z
  // seen from -z shows only back faces).
  TriangleMesh quad_back;
  quad_back.add_triangle({-1, -1, 0}, {-1, 1, 0}, {1, 1, 0});  // clockwise from +z: faces -z
  BBox box{{-1, -1, -0.5f}, {1, 1, 0.5f}};
  EXPECT_LT(view_direction(View::iso, box, quad_back).z, 0);
  TriangleMesh quad_front;
  quad_front.add_triangle({-1, -1, 0}, {1, -1, 0}, {1, 1, 0});
  EXPECT_GT(view_direction(View::iso, box, quad_front).z, 0);
  EXPECT_GT(view_direction(View::iso, box, quad_front).x, 0);  // front-right
  EXPECT_EQ(view_direction(View::top, box, quad_front).y, 1.0f);
}

TEST(DefaultView, NamedViewsAndAnExplicitCameraWork) {
  const std::string dir = test::temp_dir("default_view_named");
  const std::string cube =
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
  for (const char* view : {"iso", "front", "back", "left", "right", "top", "bottom"}) {
    const Coverage c = render_obj(dir, cube, std::string("--view ") + view);
    EXPECT_GT(c.covered, 0.3) << view;  // its silhouette spans 95 % of the narrower side
    EXPECT_GT(c.mean, 0.2) << view;
  }
  // Looking away from the model: nothing to see, and a warning says so.
  std::string err;
  const Coverage away = render_obj(dir, cube, "--eye 0,0,10 --look-at 0,0,20", &err);
  EXPECT_EQ(away.covered, 0.0);
  EXPECT_NE(err.find("the image shows only the background"), std::string::npos) << err;
  const Coverage close = render_obj(dir, cube, "--eye=0,0,3 --fov 90 --up 0,1,0", &err);
  EXPECT_GT(close.covered, 0.15);
  EXPECT_EQ(err.find("only the background"), std::string::npos) << err;
  for (const auto& [args, message] :
       {std::pair<std::string, std::string>{"--view side", "--view: unknown view 'side'"},
        {"--eye 1,2", "--eye: expected three numbers"},
        {"--fov 180", "--fov: must be between 0 and 180"},
        {"--eye 0,0,3 --look-at 0,0,3", "the eye must differ"},
        {"--eye 0,3,0 --up 0,1,0", "--up: must not be zero or parallel"}}) {
    test::write_file(dir + "/m.obj", cube);
    const auto r =
        test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/bad.png " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  }
}

// An image of nothing but the background says why: no geometry in view, or geometry that no light reaches.
TEST(DefaultView, AnUnlitViewIsToldApartFromAnEmptyOne) {
  const std::string dir = test::temp_dir("default_view_unlit");
  test::write_file(dir + "/m.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  test::write_file(dir + "/s.json", R"({"objects": [{"obj": "m.obj"}],
    "lights": [{"type": "point", "position": [0, 0, -3], "intensity": [1, 1, 1]}]})");
  const std::string render = "render -q " + dir + "/s.json --width 16 --height 16 -o " + dir + "/o.png ";
  auto r = test::run_cli(render);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("of 256 camera rays hit it) but no light reaches"), std::string::npos) << r.err;
  r = test::run_cli(render + "--eye 0,0,10 --look-at 0,0,20");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the camera sees no geometry"), std::string::npos) << r.err;
  r = test::run_cli(render + "--eye 0,0,-5");  // the lit side: no warning
  EXPECT_EQ(r.err.find("only the background"), std::string::npos) << r.err;
  // collinear corners only: nothing to hit, whatever the view
  test::write_file(dir + "/line.obj",
                   "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nv 0 1 0\nv 0 2 0\nv 0 3 0\nf 4 5 6\n");
  r = test::run_cli("render -q " + dir + "/line.obj --width 16 --height 16 -o " + dir + "/o.png");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the mesh's triangles (2) all have zero area"), std::string::npos) << r.err;
}

// `--up` is a direction: scaled by a power of two anywhere in its range, it gives the same frame and the
// same pixels; its range ends where the float frame would overflow or underflow.
TEST(DefaultView, UpCountsByItsDirectionAcrossItsRange) {
  const std::string dir = test::temp_dir("default_view_up_scale");
  test::write_file(dir + "/m.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  const std::string render = "render -q " + dir + "/m.obj --width 16 --height 12 --eye 0.3,0.2,3 ";
  ASSERT_EQ(test::run_cli(render + "--up 0,1,0.5 -o " + dir + "/unit.png").status, 0);
  for (const char* up : {"0,0.0000152587890625,0.00000762939453125", "0,1099511627776,549755813888"}) {
    const auto r = test::run_cli(render + "--up " + up + " -o " + dir + "/scaled.png");
    ASSERT_EQ(r.status, 0) << up << ": " << r.err;
    const auto same = test::run_cli("compare --max-pixel 0 " + dir + "/unit.png " + dir + "/scaled.png");
    EXPECT_EQ(same.status, 0) << up << ": " << same.out;
  }
  for (const char* up : {"0,1e-7,0", "0,2e16,0"}) {
    const auto r = test::run_cli(render + "--up " + up + " -o " + dir + "/bad.png");
    EXPECT_EQ(r.status, 2) << up;
    EXPECT_NE(r.err.find("--up: needs its largest component between 1e-6 and 1e16"), std::string::npos)
        << r.err;
  }
}

}  // namespace
}  // namespace rayvec

namespace rayvec {
namespace {

TEST(RenderDefaults, IntersectorIsWatertightUnlessChosen) {
  const std::string dir = test::temp_dir("render_default_intersector");
  test::write_file(dir + "/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto r = test::run_cli("render -q --stats " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/o.png");
  EXPECT_NE(r.out.find("intersector: watertight"), std::string::npos) << r.out;
  r = test::run_cli("render -q --stats " + dir + "/m.obj --width 8 --height 8 -o " + dir +
                    "/o.png --intersector mt");
  EXPECT_NE(r.out.find("intersector: mt"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rayvec
