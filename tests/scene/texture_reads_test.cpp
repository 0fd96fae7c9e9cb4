// texture_reads: a model's texture files read several at once give the scene that reading them one
// by one gives — the same textures at the same indices, the same warnings in the same order.
#include "scene/texture_reads.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image_io.h"
#include "scene/scene.h"
#include "test_support.h"

namespace rayvec {
namespace {

// A PNG of w×h pixels of one colour.
void write_png(const std::string& path, int w, int h, float r, float g, float b) {
  Image img(w, h, {"R", "G", "B"});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.at(x, y, 0) = r;
      img.at(x, y, 1) = g;
      img.at(x, y, 2) = b;
    }
  write_image(path, img);
}

// Five PNGs of different sizes and colours, a file that is not an image and a name with no file.
std::string make_textures(const std::string& dir) {
  for (int i = 0; i < 5; ++i)
    write_png(dir + "/t" + std::to_string(i) + ".png", 3 + i, 2 + 2 * i, 0.1f * float(i), 0.5f,
              1.0f - 0.2f * float(i));
  test::write_file(dir + "/junk.png", "\x89PNG\r\n\x1a\n but nothing after the signature");
  return dir;
}

TEST(TextureReads, ResultsComeInTheOrderOfThePaths) {
  const std::string dir = make_textures(test::temp_dir("texture_reads_order"));
  const std::vector<std::string> paths = {dir + "/t3.png",   dir + "/junk.png", dir + "/t0.png",
                                          dir + "/none.png", dir + "/t4.png",   dir + "/t1.png"};
  for (const int threads : {1, 2, 4, 16}) {
    const std::vector<TextureRead> reads = read_texture_files(paths, threads);
    ASSERT_EQ(reads.size(), paths.size());
    EXPECT_EQ(reads[0].texture.width(), 6) << threads;
    EXPECT_NE(reads[1].problem.find("cannot be decoded: "), std::string::npos) << threads;
    EXPECT_EQ(reads[2].texture.width(), 3) << threads;
    EXPECT_EQ(reads[3].problem, "not found") << threads;
    EXPECT_EQ(reads[4].texture.height(), 10) << threads;
    EXPECT_EQ(reads[5].texture.width(), 4) << threads;
    for (const TextureRead& r : reads) EXPECT_FALSE(r.failure);
  }
  EXPECT_TRUE(read_texture_files({}, 4).empty());
}

TEST(TextureReads, SceneIsTheSameWhateverTheThreadCount) {
  const std::string dir = make_textures(test::temp_dir("texture_reads_scene"));
  // nine materials naming the five textures (some twice), the junk file and a missing one
  const char* maps[] = {"t2.png",   "t0.png", "junk.png", "t2.png", "t4.png",
                        "none.png", "t1.png", "t3.png",   "t0.png"};
  std::string mtl, obj = "mtllib m.mtl\nvt 0 0\nvt 1 0\nvt 0 1\n";
  for (int i = 0; i < 9; ++i) {
    mtl += "newmtl m" + std::to_string(i) + "\nKd 1 1 1\nmap_Kd " + maps[i] + "\n";
    obj +=
        "v " + std::to_string(i) + " 0 0\nv " + std::to_string(i) + " 1 0\nv " + std::to_string(i) + " 0 1\n";
    obj += "usemtl m" + std::to_string(i) + "\nf " + std::to_string(3 * i + 1) + "/1 " +
           std::to_string(3 * i + 2) + "/2 " + std::to_string(3 * i + 3) + "/3\n";
  }
  test::write_file(dir + "/m.mtl", mtl);
  test::write_file(dir + "/m.obj", obj);
  const Scene one = load_scene(dir + "/m.obj", 1);
  EXPECT_EQ(one.textures.size(), 5u);
  EXPECT_EQ(one.warnings.size(), 2u);
  for (const int threads : {2, 3, 8}) {
    SCOPED_TRACE(threads);
    const Scene many = load_scene(dir + "/m.obj", threads);
    EXPECT_EQ(many.warnings, one.warnings);
    EXPECT_EQ(many.material_texture, one.material_texture);
    ASSERT_EQ(many.textures.size(), one.textures.size());
    for (std::size_t t = 0; t < one.textures.size(); ++t) {
      ASSERT_EQ(many.textures[t].width(), one.textures[t].width());
      ASSERT_EQ(many.textures[t].height(), one.textures[t].height());
      const Vec3f a = many.textures[t].texel(1, 1), b = one.textures[t].texel(1, 1);
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.z, b.z);
    }
    for (std::size_t m = 0; m < one.materials.size(); ++m)
      EXPECT_EQ(many.materials[m].map_Kd, one.materials[m].map_Kd);
  }
}

}  // namespace
}  // namespace rayvec
