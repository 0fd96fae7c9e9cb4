// Decompression bombs: image files whose header declares far more pixels than the file holds (or
// than the input limit allows) are refused before any pixel is decoded, with a message naming the
// file, the declared size and how to raise the limit: exit 2 from compare, a warning from render
// (an error with --strict).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "image/crafted_images.h"
#include "image/exr_module_abi.h"
#include "image/image_budget.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "platform/plugin.h"
#include "test_support.h"

namespace rayvec {
namespace {

std::string message_of(const std::string& path) {
  try {
    read_image(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

// The path of a reproducer in tests/data/fuzz/.
std::string fuzz_file(const std::string& name) { return std::string(RAYVEC_TEST_DATA) + "/fuzz/" + name; }

// Reading the reproducer `name` fails with an InputError whose message holds `expected`.
void expect_refused(const std::string& name, const std::string& expected) {
  const std::string m = message_of(fuzz_file(name));
  EXPECT_NE(m.find(expected), std::string::npos) << m;
}

std::string small_exr(const std::string& dir) {
  write_image(dir + "/small.exr", Image(4, 4, {"R", "G", "B"}));
  return test::read_file(dir + "/small.exr");
}

TEST(ImageBudget, PngDeclaringMoreThanTheInputLimitIsRefusedByName) {
  const std::string dir = test::temp_dir("bomb_png");
  const std::string bomb = test::png_claiming(30000, 30000);
  EXPECT_LT(bomb.size(), 200u);
  test::write_file(dir + "/bomb.png", bomb);
  const std::string m = message_of(dir + "/bomb.png");
  EXPECT_NE(m.find("bomb.png: declares a 30000x30000 image with 3 channels"), std::string::npos) << m;
  EXPECT_NE(m.find("RAYVEC_MAX_INPUT_MB"), std::string::npos) << m;
  test::write_file(dir + "/huge.png", test::png_claiming(65535, 65535));
  EXPECT_NE(message_of(dir + "/huge.png").find("huge.png: declares a 65535x65535"), std::string::npos);
}

TEST(ImageBudget, PngDeclaringMoreThanItsBytesCanHoldIsRefusedBeforeDecoding) {
  const std::string dir = test::temp_dir("bomb_png_ratio");
  test::write_file(dir + "/lie.png", test::png_claiming(12000, 12000));  // 1.7 GB of floats: within the limit
  const std::string m = message_of(dir + "/lie.png");
  EXPECT_NE(m.find("lie.png: declares a 12000x12000 image"), std::string::npos) << m;
  EXPECT_NE(m.find("too few for any compressed form"), std::string::npos) << m;
}

TEST(ImageBudget, ExrDeclaringMoreThanTheInputLimitIsRefusedByName) {
  const std::string dir = test::temp_dir("bomb_exr");
  test::write_file(dir + "/bomb.exr", test::exr_claiming(small_exr(dir), 30000, 30000));
  const std::string m = message_of(dir + "/bomb.exr");
  EXPECT_NE(m.find("bomb.exr: declares a 30000x30000 image with 3 channels"), std::string::npos) << m;
  EXPECT_NE(m.find("RAYVEC_MAX_INPUT_MB"), std::string::npos) << m;
}

TEST(ImageBudget, ExrHoldingFewerRowsThanDeclaredFailsByName) {
  const std::string dir = test::temp_dir("bomb_exr_rows");
  test::write_file(dir + "/lie.exr", test::exr_claiming(small_exr(dir), 12000, 12000));
  const std::string m = message_of(dir + "/lie.exr");
  EXPECT_EQ(m.rfind(dir + "/lie.exr: ", 0), 0u) << m;
}

TEST(ImageBudget, LimitFollowsRayvecMaxInputMb) {
  const std::string dir = test::temp_dir("budget_env");
  write_image(dir + "/a.png", Image(600, 600, {"R", "G", "B"}));  // 4.3 MB as floats
  ::setenv("RAYVEC_MAX_INPUT_MB", "4", 1);
  const std::string m = message_of(dir + "/a.png");
  ::unsetenv("RAYVEC_MAX_INPUT_MB");
  EXPECT_NE(m.find("a.png: declares a 600x600 image with 3 channels, 4 MB once decoded, more than the 4 MB"),
            std::string::npos)
      << m;
  EXPECT_EQ(read_image(dir + "/a.png").width, 600);
}

TEST(ImageBudget, CommandsThatDecodeImagesExitTwoNamingTheFile) {
  const std::string dir = test::temp_dir("bomb_cli");
  test::write_file(dir + "/bomb.png", test::png_claiming(30000, 30000));
  write_image(dir + "/ok.png", Image(4, 4, {"R", "G", "B"}));
  const auto cmp = test::run_cli("compare '" + dir + "/bomb.png' '" + dir + "/bomb.png'");
  EXPECT_EQ(cmp.status, 2) << cmp.err;
  EXPECT_NE(cmp.err.find("bomb.png: declares a 30000x30000"), std::string::npos) << cmp.err;

  test::write_file(dir + "/quad.mtl", "newmtl t\nKd 1 1 1\nmap_Kd bomb.png\n");
  test::write_file(
      dir + "/quad.obj",
      "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nusemtl t\nf 1/1 2/2 3/3\n");
  // render: a texture that cannot be decoded is a warning naming it (drawn with Kd only); --strict
  // makes it an error.
  const auto render = test::run_cli("render '" + dir + "/quad.obj' -o '" + dir + "/out.png' --quiet");
  EXPECT_EQ(render.status, 0) << render.err;
  EXPECT_NE(render.err.find("bomb.png: declares a 30000x30000"), std::string::npos) << render.err;
  const auto strict =
      test::run_cli("render '" + dir + "/quad.obj' -o '" + dir + "/out.png' --quiet --strict");
  EXPECT_EQ(strict.status, 2) << strict.err;
  EXPECT_NE(strict.err.find("bomb.png: declares a 30000x30000"), std::string::npos) << strict.err;
}

// Found by fuzz_image: an attribute of unknown type whose size field says 1.7 GB in a 325-byte file;
// OpenEXR's C++ reader allocated it before reading (libFuzzer: out-of-memory).
TEST(ImageBudget, ExrAttributeLargerThanTheFileIsRefused) {
  expect_refused("exr_attribute_claims_1.7GB.exr",
                 "exr_attribute_claims_1.7GB.exr: cannot read EXR: attribute 'rayvecv/1\\x01\\x02' "
                 "declares 1718571776 bytes");
}

// Found by fuzz_image: an 80-byte attribute name in a file without the long-names flag. OpenEXR's
// C++ reader took the first 31 bytes as the name and parsed the rest out of step, into an
// attribute of 1.7 GB.
TEST(ImageBudget, ExrAttributeNameTooLongIsRefused) {
  expect_refused("exr_attribute_name_too_long.exr",
                 "exr_attribute_name_too_long.exr: cannot read EXR: an attribute name longer than 31 bytes");
}

// Found by fuzz_image (a heap overwrite that only showed as libFuzzer's own state corrupted): a
// header that gives dataWindow twice, a 2x2 window and then the true 5x3 one. OpenEXRCore sized the
// pixel buffer by the first, the C++ reader wrote the second's rows into it.
TEST(ImageBudget, ExrAttributeGivenTwiceIsRefused) {
  expect_refused("exr_data_window_given_twice.exr",
                 "exr_data_window_given_twice.exr: cannot read EXR: attribute 'dataWindow' of type box2i: "
                 "given twice in one header");
}

// Found by fuzz_image (out of memory): a 1.2 KB tiled EXR whose `tiles` attribute says 7405584x16
// pixels. OpenEXR's C++ reader allocates a buffer of one whole tile (2.1 GB in halves) when the file
// is opened, whatever the data window; the tile is now checked against the input limit like an image.
TEST(ImageBudget, ExrTileLargerThanTheInputLimitIsRefused) {
  expect_refused(
      "exr_tile_claims_7405584x16.exr",
      "exr_tile_claims_7405584x16.exr: declares tiles of 7405584x16 pixels with 9 channels (a whole "
      "tile is decoded at once)");
  const Image tiled = read_image(std::string(RAYVEC_TEST_DATA) + "/fuzz_corpus/image/half_tiled_piz.exr");
  EXPECT_GT(tiled.width, 0) << "a tiled EXR with small tiles still reads";
}

// The module does not rely on the binary's attribute walk: handed the same file directly, it refuses
// to decode pixels into a buffer laid out by the header OpenEXRCore read.
TEST(ImageBudget, ExrModuleRefusesAHeaderItsTwoParsersReadDifferently) {
  const Plugin p = open_plugin("RAYVEC_EXR_MODULE", kExrModuleName, /*global=*/false);
  ASSERT_NE(p.handle, nullptr) << plugin_problem(p, kExrModuleName, "RAYVEC_EXR_MODULE");
  const auto entry = reinterpret_cast<RayvecExrModuleFn>(plugin_symbol(p, "rayvec_exr_module"));
  ASSERT_NE(entry, nullptr);
  const RayvecExrModule& m = *entry();
  const std::string path = fuzz_file("exr_data_window_given_twice.exr");
  void* file = nullptr;
  RayvecExrInfo info{};
  char error[512] = "";
  ASSERT_EQ(m.open(path.c_str(), &file, &info, error, sizeof error), kRayvecExrOk) << error;
  EXPECT_EQ(info.width, 2);  // the first dataWindow
  EXPECT_EQ(info.height, 2);
  std::vector<float> pixels(std::size_t(info.width) * std::size_t(info.height) * std::size_t(info.channels));
  std::vector<const char*> names;
  for (int c = 0; c < info.channels; ++c) names.push_back(m.channel(file, c));
  EXPECT_EQ(
      m.read_rows(file, names.data(), info.channels, pixels.data(), 0, info.height, error, sizeof error),
      kRayvecExrBadInput);
  EXPECT_NE(std::string(error).find("two header parsers disagree"), std::string::npos) << error;
  m.close(file);
}

// Found by fuzz_image: a 458753x1 EXR whose one pixel chunk is cut off by the end of the file.
// OpenEXR's C++ reader decoded it from a buffer it never filled and reported success.
TEST(ImageBudget, ExrChunkCutOffByTheEndOfTheFileIsRefused) {
  expect_refused("exr_chunk_cut_off.exr", "exr_chunk_cut_off.exr: cannot read EXR: pixel data: ");
}

// Found by fuzz_image with the same file: within the limit as stored (two channels), but a texture
// is held as three. A grey image is checked as what it becomes.
TEST(ImageBudget, TextureIsCheckedAsTheRgbItBecomes) {
  const std::string dir = test::temp_dir("budget_texture");
  const std::string grey = std::string("P5\n400 400\n255\n") + std::string(400 * 400, '\x80');
  test::write_file(dir + "/grey.pgm", grey);  // 0.64 MB as one float channel, 1.92 MB as RGB
  ::setenv("RAYVEC_MAX_INPUT_MB", "1", 1);
  std::string m = "(no InputError)";
  EXPECT_EQ(read_image(dir + "/grey.pgm").nchannels(), 1);
  try {
    read_texture(dir + "/grey.pgm");
  } catch (const InputError& e) {
    m = e.what();
  }
  ::unsetenv("RAYVEC_MAX_INPUT_MB");
  EXPECT_NE(
      m.find("grey.pgm: is a 400x400 texture, counted as RGB floats, 2 MB once decoded, more than the 1 MB"),
      std::string::npos)
      << m;
  const Texture tex = read_texture(dir + "/grey.pgm");  // grey widened: three equal channels
  EXPECT_EQ(tex.width(), 400);
  EXPECT_EQ(tex.texel(7, 9).x, tex.texel(7, 9).z);
}

// Found by fuzz_image: a channel list that ends before its declared size. OpenEXR's C++ reader
// reads typed attributes by their own layout, went on out of step and allocated 1.7 GB.
TEST(ImageBudget, ExrTypedAttributeThatDoesNotFillItsSizeIsRefused) {
  expect_refused(
      "exr_channel_list_short_of_its_size.exr",
      "cannot read EXR: attribute 'channels' of type chlist: the channel list does not fill its 178");
}

// Found by fuzz_image: a tEXt chunk whose length says 1.8 GB in a small file; libpng allocated it
// before reading.
TEST(ImageBudget, PngChunkLongerThanTheFileIsRefused) {
  expect_refused("png_text_chunk_claims_1.8GB.png",
                 "png_text_chunk_claims_1.8GB.png: cannot read PNG: chunk 'tEXt' declares 1852133234 bytes");
}

TEST(ImageBudget, DecodedBytesAreFloatsPerChannel) {
  EXPECT_EQ(decoded_image_bytes(10, 20, 3), 10u * 20u * 3u * 4u);
  EXPECT_EQ(decoded_image_bytes(0, 20, 3), 0u);
  EXPECT_THROW(check_declared_image_size("x.png", -1, 5, 3), InputError);
}

}  // namespace
}  // namespace rayvec
