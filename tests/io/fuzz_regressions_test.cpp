// Inputs the fuzz harnesses (tests/fuzz/) found crashing or hitting undefined behaviour, kept in
// tests/data/fuzz/ as they were found; each must now be a clean InputError naming what is wrong.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <utility>

#include "io/input_error.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kFuzz = std::string(RAYVEC_TEST_DATA) + "/fuzz/";

template <typename Load>
std::string input_error_of(Load load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(FuzzRegressions, SkinWeightJointIdBeyondIntIsRejected) {
  // `vw 0 2222222224`: tinyobjloader converted the joint id to int (UBSan: float-cast-overflow).
  const std::string path = kFuzz + "obj_vw_joint_overflow.obj";
  EXPECT_EQ(input_error_of([&] { load_obj(path); }),
            path +
                ":1: `vw` joint id '2222222224' is not a plain decimal number below 2^31 (digits, "
                "an optional sign and decimal point)");
}

TEST(FuzzRegressions, SkinWeightJointIdThatTinyobjloaderReadsAsNanIsRejected) {
  // `vw 0 0e0000001000000ad1`: strtod reads 0, but tinyobjloader's parser multiplies the zero
  // mantissa by 10^1000000 (NaN) and converted that to int (UBSan: float-cast-overflow). The file's
  // `vt` line two has such a number too (a NaN texture coordinate), now refused there as a `vt`'s
  // second value that is not a number; and a joint id must still be a plain decimal.
  const std::string path = kFuzz + "obj_vw_joint_nan.obj";
  EXPECT_EQ(input_error_of([&] { load_obj(path); }),
            path + ":2: `vt` coordinate 2 '0e0000001000000QQQQQQQQQQQQQQQQQQQQQQQ01' is not a finite number");
  const std::string dir = test::temp_dir("fuzz_joint");
  test::write_file(dir + "/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nvw 0 0e5ad1\n");
  EXPECT_EQ(input_error_of([&] { load_obj(dir + "/m.obj"); }),
            dir +
                "/m.obj:5: `vw` joint id '0e5ad1' is not a plain decimal number below 2^31 (digits, an "
                "optional sign and decimal point)");
}

TEST(FuzzRegressions, AVertexColourBeyondFloatRangeIsRejected) {
  // `v 0 0 0 1 0<BS>f 1555…5mtllibo`: tinyobjloader reads a colour's components as far as they look
  // like numbers, so fifty digits with a word after them made an infinite colour (the message shows
  // the first 40 bytes of the token).
  const std::string path = kFuzz + "obj_colour_beyond_float.obj";
  EXPECT_EQ(input_error_of([&] { load_obj(path); }), path + ":1: `v` colour component 3 '" +
                                                         std::string(40, '5').replace(0, 1, "1") +
                                                         "...' is not a finite number (colours are 0 to 1)");
  const std::string dir = test::temp_dir("fuzz_colour");
  for (const char* colour : {"1 0 1e39", "1 -1e39 0", "-inf 0 0", "1 0 3.5e38"}) {
    test::write_file(dir + "/m.obj", std::string("v 0 0 0\nv 1 0 0 ") + colour + "\nv 0 1 0\nf 1 2 3\n");
    for (const bool reference : {false, true})
      EXPECT_NE(input_error_of([&] {
                  load_obj(dir + "/m.obj", {.reference = reference});
                }).find("m.obj:2: `v` colour component"),
                std::string::npos)
          << colour;
  }
  // not colours as tinyobjloader reads them (a word among the three): white, no error
  test::write_file(dir + "/m.obj", "v 0 0 0 1 x 1e39\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NO_THROW(load_obj(dir + "/m.obj"));
}

TEST(FuzzRegressions, ExponentsOfMoreThanTwoDigitsAreRejectedOnEveryLineTinyobjloaderParses) {
  // tinyobjloader's exponent check lets 2147483648 and 2147483649 overflow its int (UBSan:
  // signed-integer-overflow), and from 10^442 on it multiplies a zero mantissa by infinity: NaN
  // where the text means 0 (`v 0e1000` became a NaN vertex). Each line is refused by the check
  // before tinyobjloader, beside a polyline (`l`) or a face; the fast reader, which takes both,
  // must leave such a line to that path and so give the same error.
  const std::string dir = test::temp_dir("fuzz_exponent");
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 2 0\n";
  const std::string polyline = vertices + "l 1 2 3 4 5\n", triangle = vertices + "f 1 2 3\n";
  const std::tuple<std::string, const char*, const char*> cases[] = {
      {polyline, "v 0e2147483649 0 0\n", "0e2147483649"},
      {polyline, "vn 0 0 0E+0002147483648\n", "0E+0002147483648"},
      {polyline, "vt 0 -.5e-2147483649\n", "-.5e-2147483649"},
      {polyline, "vw 0 1 0e2147483649\n", "0e2147483649"},
      {polyline, "t crease 0/1/0 1.0e2147483649\n", "1.0e2147483649"},
      {polyline, "v 0 0 0 1 0e9999999999 1\n", "0e9999999999"},
      {polyline, "v 0e1000 0 0\n", "0e1000"},
      {polyline, "vn 0 0 1e-100\n", "1e-100"},
      {triangle, "v 0e1000 0 0\n", "0e1000"},
      {triangle, "vt 0 0e0000001000000041\n", "0e0000001000000041"}};
  for (const auto& [faces, line, token] : cases) {
    test::write_file(dir + "/m.obj", faces + line);
    EXPECT_EQ(input_error_of([&] { load_obj(dir + "/m.obj"); }),
              dir + "/m.obj:7: number '" + token +
                  "' has an exponent of more than 2 digits (a float needs at most 2: 3.4e38 to 1.4e-45)")
        << line;
  }
  test::write_file(dir + "/m.obj",
                   vertices + "f 1 2 3 4 5\nv 0 0 1e000000000003\nvt 0.5 1.4e-45\nvn 0 0 -3.4E+38\n");
  EXPECT_NO_THROW(load_obj(dir + "/m.obj"));  // two digits, leading zeros not counted
}

TEST(FuzzRegressions, ATextureCoordinatesSecondValueMustBeAFiniteFloat) {
  // Found while reviewing the exponent rule: obj_scan checked only a `vt`'s first value, while
  // tinyobjloader reads the second too, so `vt 0 1e39` (or 320 digits) gave an infinite texture
  // coordinate on both readers (the fast one leaves the line to the reference path). A comment
  // after the first value is still allowed.
  const std::string dir = test::temp_dir("fuzz_vt_second");
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n";
  test::write_file(dir + "/m.obj", tri + "vt 0 1e39\n");
  EXPECT_EQ(input_error_of([&] { load_obj(dir + "/m.obj"); }),
            dir + "/m.obj:5: `vt` coordinate 2 '1e39' is not a finite number");
  test::write_file(dir + "/m.obj", tri + "vt 0 " + std::string(320, '1') + "\n");
  EXPECT_NE(input_error_of([&] { load_obj(dir + "/m.obj"); }).find(":5: `vt` coordinate 2 '111"),
            std::string::npos);
  test::write_file(dir + "/m.obj", tri + "vt 0.5 # one value\n");
  EXPECT_NO_THROW(load_obj(dir + "/m.obj"));
}

TEST(FuzzRegressions, JsonNumberOverflowIsAnInputError) {
  // nlohmann throws out_of_range (not parse_error) for 3.3e341: it escaped as an uncaught exception.
  const std::string path = kFuzz + "scene_number_overflow.json";
  EXPECT_EQ(input_error_of([&] { load_scene_json(path); }),
            path + ":1: invalid JSON: number overflow parsing '33333333.3331333e334'");
}

TEST(FuzzRegressions, TextureNameTooLongForTheFileSystemIsAWarning) {
  // Found by fuzz_obj: a `map_Kd` name of more than 255 bytes made the throwing form of
  // std::filesystem::exists raise ENAMETOOLONG as an uncaught filesystem_error (abort). The texture
  // must be reported like a missing one: a warning naming the MTL line, the material drawn with Kd
  // (an error with --strict).
  const std::string dir = test::temp_dir("fuzz_texture_name");
  const std::string name(300, 'x');
  test::write_file(dir + "/m.obj", "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_file(dir + "/m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd " + name + ".png\n");
  const ObjModel model = load_obj(dir + "/m.obj");
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_NE(model.warnings[0].find("m.mtl:3: material 'a': texture '" + name + ".png' (" + dir + "/" + name +
                                   ".png) cannot be looked up: File name too long"),
            std::string::npos)
      << model.warnings[0];
  auto r = test::run_cli("render '" + dir + "/m.obj' -o '" + dir + "/out.png' --width 8 --height 8");
  EXPECT_EQ(r.status, 0) << r.err;
  r = test::run_cli("render '" + dir + "/m.obj' -o '" + dir + "/out.png' --width 8 --height 8 --strict");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("File name too long"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rayvec
