// A quad rendered head-on through the CLI, for tests of what colours a surface: the test gives
// quad.obj (x, y in [-1, 1], z = 0) and its quad.mtl; the scene looks at it from z = 3 (fov_y 60°,
// 40×20 pixels) under a directional light of irradiance π along −z, without ambient light, so a
// Lambertian surface (illum 1) reads back as its albedo: Kd·c/π · E·cos 0.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "test_support.h"

namespace rayvec::test {

inline constexpr int kQuadImageWidth = 40, kQuadRow = 10;

// Writes `mtl` and `obj` as DIR/quad.mtl and DIR/quad.obj, renders them as above into DIR/out.exr
// and returns the image (empty on failure).
inline Image render_headon_quad(const std::string& dir, const std::string& mtl, const std::string& obj) {
  write_file(dir + "/quad.mtl", mtl);
  write_file(dir + "/quad.obj", obj);
  const std::string pi = std::to_string(3.14159265f);
  write_file(dir + "/scene.json",
             "{ \"camera\": { \"eye\": [0, 0, 3], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0],"
             " \"fov_y\": 60, \"width\": 40, \"height\": 20 },"
             " \"background\": [0, 0, 0], \"ambient\": [0, 0, 0],"
             " \"lights\": [ { \"type\": \"directional\", \"direction\": [0, 0, -1],"
             " \"irradiance\": [" +
                 pi + ", " + pi + ", " + pi +
                 "] } ], \"objects\": [ { \"obj\": \"quad.obj\" } ],"
                 " \"render\": { \"spp\": 1 } }");
  const auto r = run_cli("render '" + dir + "/scene.json' -o '" + dir + "/out.exr' --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? read_image(dir + "/out.exr") : Image();
}

// The world x on the quad under the centre of pixel column px (the camera's half-width at the
// quad's distance is 3·tan 30° times the aspect ratio 2).
inline double headon_quad_x(int px) {
  const double half_width = 3.0 * std::tan(30.0 * 3.141592653589793 / 180.0) * 2.0;
  return ((px + 0.5) / kQuadImageWidth * 2.0 - 1.0) * half_width;
}

// Expects pixel column px (row kQuadRow) of `img` to read (r, g, b) within 2e-3.
inline void expect_quad_colour(const Image& img, int px, double r, double g, double b,
                               const std::string& what) {
  EXPECT_NEAR(img.at(px, kQuadRow, 0), r, 2e-3) << what << ": pixel " << px;
  EXPECT_NEAR(img.at(px, kQuadRow, 1), g, 2e-3) << what << ": pixel " << px;
  EXPECT_NEAR(img.at(px, kQuadRow, 2), b, 2e-3) << what << ": pixel " << px;
}

// Calls check(px, x) for every pixel column px of `img` whose centre lies on the quad away from its
// silhouette (|x| <= 0.95, x the world x there); returns how many it called.
template <typename Check>
int for_each_quad_column(const Image& img, Check check) {
  if (img.width != kQuadImageWidth) {
    ADD_FAILURE() << "the quad's image is " << img.width << " pixels wide";
    return 0;
  }
  int count = 0;
  for (int px = 0; px < kQuadImageWidth; ++px) {
    const double x = headon_quad_x(px);
    if (std::abs(x) > 0.95) continue;
    check(px, x);
    ++count;
  }
  return count;
}

}  // namespace rayvec::test
