// jpeg_file: JPEGs read by libjpeg give OpenImageIO's pixels bit for bit; CMYK goes to OpenImageIO;
// truncated, corrupt, oversized and endlessly progressive files are refused naming the file.
// tests/data/images/jpeg: rgb420.jpg (13x7, 4:2:0), grey.jpg (9x5) and prog.jpg (21x11,
// progressive) written by oiiotool from --pattern fill gradients; cmyk.jpg (6x4) by libjpeg with
// in_color_space JCS_CMYK.
#include "image/jpeg_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "image/oiio_module.h"
#include "io/input_error.h"
#include "test_support.h"

namespace rayvec {
namespace {

const std::string kJpegDir = std::string(RAYVEC_TEST_DATA) + "/images/jpeg/";

// The JPEGs the differential test reads: the tree's own, and every one in Debian's
// assimp-testmodels when installed (photographs and textures from many encoders).
std::vector<std::string> jpegs_to_compare() {
  std::vector<std::string> paths = {kJpegDir + "rgb420.jpg", kJpegDir + "grey.jpg", kJpegDir + "prog.jpg"};
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator("/usr/share/assimp/models", ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    std::string ext = it->path().extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (it->is_regular_file() && (ext == ".jpg" || ext == ".jpeg")) paths.push_back(it->path().string());
  }
  return paths;
}

TEST(JpegFile, ReadsTheSamePixelsAsOpenImageIo) {
  int compared = 0;
  for (const std::string& path : jpegs_to_compare()) {
    SCOPED_TRACE(path);
    std::optional<Image> ours;
    try {
      ours = read_jpeg(path);
    } catch (const InputError& e) {
      // a file libjpeg cannot read must be one OpenImageIO cannot read either
      bool encoded = false;
      EXPECT_ANY_THROW(read_with_oiio_module(path, &encoded)) << e.what();
      continue;
    }
    if (!ours) continue;  // CMYK: OpenImageIO's
    bool encoded = false;
    const Image theirs = read_with_oiio_module(path, &encoded);
    EXPECT_TRUE(encoded);
    ASSERT_EQ(ours->width, theirs.width);
    ASSERT_EQ(ours->height, theirs.height);
    ASSERT_EQ(ours->channels, theirs.channels);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < ours->pixels.size(); ++i) differ += ours->pixels[i] != theirs.pixels[i];
    EXPECT_EQ(differ, 0u) << "of " << ours->pixels.size() << " values";
    ++compared;
  }
  EXPECT_GE(compared, 3);
  std::printf("compared %d JPEGs with OpenImageIO's reading\n", compared);
}

TEST(JpegFile, GreyAndColourChannelsAreNamedAsOpenImageIoNamesThem) {
  const std::optional<Image> grey = read_jpeg(kJpegDir + "grey.jpg");
  ASSERT_TRUE(grey);
  EXPECT_EQ(grey->channels, std::vector<std::string>{"Y"});
  EXPECT_EQ(grey->width, 9);
  EXPECT_EQ(grey->height, 5);
  // top 0.1, bottom 0.9: the rows get lighter downwards
  EXPECT_LT(grey->at(4, 0, 0), grey->at(4, 4, 0));
  const Texture tex = read_texture(kJpegDir + "rgb420.jpg");
  EXPECT_EQ(tex.width(), 13);
  EXPECT_GT(tex.texel(0, 0).x, 0.5f);  // the red corner (its chroma shared with neighbours: 4:2:0)
  EXPECT_LT(tex.texel(0, 0).z, 0.1f);
}

TEST(JpegFile, CmykIsLeftToOpenImageIo) {
  EXPECT_FALSE(read_jpeg(kJpegDir + "cmyk.jpg"));
  const Image image = read_image(kJpegDir + "cmyk.jpg");
  EXPECT_EQ(image.width, 6);
  EXPECT_EQ(image.nchannels(), 3);
}

std::string expect_input_error(const std::string& path) {
  try {
    read_image(path);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << path << " was read";
  return "";
}

// The offset of the first marker `code` (FF code) after the start of image, or npos.
std::size_t find_marker(const std::string& jpeg, unsigned char code, std::size_t from = 2) {
  for (std::size_t i = from; i + 1 < jpeg.size(); ++i)
    if (static_cast<unsigned char>(jpeg[i]) == 0xff && static_cast<unsigned char>(jpeg[i + 1]) == code)
      return i;
  return std::string::npos;
}

TEST(JpegFile, FileCutInsideItsImageDataIsRefused) {
  // libjpeg alone would finish the image in grey with a warning
  const std::string bytes = test::read_file(kJpegDir + "rgb420.jpg");
  const std::size_t scan = find_marker(bytes, 0xda);
  ASSERT_NE(scan, std::string::npos);
  const std::string path = test::temp_dir("jpeg_cut") + "/cut.jpg";
  test::write_file(path, bytes.substr(0, scan + (bytes.size() - scan) / 2));
  EXPECT_NE(
      expect_input_error(path).find("cut.jpg: cannot read JPEG: the file ends before its image data does"),
      std::string::npos);
  test::write_file(path, bytes.substr(0, scan));  // cut before its first scan: libjpeg's own error
  EXPECT_NE(expect_input_error(path).find("cut.jpg: cannot read JPEG: "), std::string::npos);
}

TEST(JpegFile, CorruptHeaderIsRefused) {
  const std::string path = test::temp_dir("jpeg_header") + "/bad.jpg";
  test::write_file(path, std::string("\xff\xd8\xff\xe0\x00\x10JFIF\x00 not a JPEG at all", 29));
  EXPECT_NE(expect_input_error(path).find("cannot read JPEG"), std::string::npos);
}

TEST(JpegFile, DeclaredSizeIsCheckedBeforeDecoding) {
  std::string bytes = test::read_file(kJpegDir + "rgb420.jpg");
  const std::size_t sof = find_marker(bytes, 0xc0);
  ASSERT_NE(sof, std::string::npos);
  // SOF0: FF C0, length (2), precision (1), height (2), width (2)
  bytes[sof + 5] = bytes[sof + 7] = char(0xea);
  bytes[sof + 6] = bytes[sof + 8] = char(0x60);  // 60000 x 60000
  const std::string path = test::temp_dir("jpeg_size") + "/big.jpg";
  test::write_file(path, bytes);
  EXPECT_NE(expect_input_error(path).find("declares a 60000x60000 image"), std::string::npos);
}

TEST(JpegFile, ProgressiveFileWithTooManyScansIsRefused) {
  // the last scan of prog.jpg repeated until there are more than kMaxJpegScans: libjpeg only
  // warns about such a bogus progression, and would decode every repeat
  const std::string bytes = test::read_file(kJpegDir + "prog.jpg");
  std::size_t last_scan = std::string::npos;
  for (std::size_t at = find_marker(bytes, 0xda); at != std::string::npos;
       at = find_marker(bytes, 0xda, at + 2))
    last_scan = at;
  const std::size_t end = find_marker(bytes, 0xd9);
  ASSERT_NE(last_scan, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  std::string hostile = bytes.substr(0, end);
  for (int i = 0; i < kMaxJpegScans; ++i) hostile += bytes.substr(last_scan, end - last_scan);
  hostile += bytes.substr(end);
  const std::string path = test::temp_dir("jpeg_progressive") + "/many.jpg";
  test::write_file(path, hostile);
  EXPECT_NE(expect_input_error(path).find("more than 500 progressive scans"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
