// The attribute walk of an EXR header, in plain stdio: no OpenEXR here (the library is in the module
// librayvec_exr.so, exr_module.cpp), so a corrupt header is refused before the module is asked to
// parse it.
#include "image/exr_header.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <set>
#include <utility>

#include "image/image_budget.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

// A name from the file as printable ASCII: other bytes as \xNN.
std::string printable(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(char(c));
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    }
  }
  return out;
}

// The value size OpenEXR's C++ reader consumes for a fixed-size attribute type (-1: any size).
long fixed_size(const std::string& type) {
  static const std::pair<const char*, long> kSizes[] = {
      {"box2i", 16},   {"box2f", 16},      {"v2i", 8},       {"v2f", 8},      {"v2d", 16},
      {"v3i", 12},     {"v3f", 12},        {"v3d", 24},      {"int", 4},      {"float", 4},
      {"double", 8},   {"compression", 1}, {"lineOrder", 1}, {"envmap", 1},   {"deepImageState", 1},
      {"tiledesc", 9}, {"rational", 8},    {"timecode", 8},  {"keycode", 28}, {"chromaticities", 32},
      {"m33f", 36},    {"m33d", 72},       {"m44f", 64},     {"m44d", 128}};
  for (const auto& [name, size] : kSizes)
    if (type == name) return size;
  return -1;
}

}  // namespace

void check_exr_attributes(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return;  // the module's open reports it
  std::fseek(f.get(), 0, SEEK_END);
  const long file_size = std::ftell(f.get());
  std::fseek(f.get(), 4, SEEK_SET);
  unsigned char version[4];
  if (std::fread(version, 1, 4, f.get()) != 4) return;
  const bool multipart = version[1] & 0x10;
  const std::size_t max_name = (version[1] & 0x04) ? 255 : 31;  // the long-names flag
  // Names longer than the limit or cut by the end of the file: the C++ library would read the
  // first max_name bytes as the name and go on parsing out of step, so they are refused here.
  auto read_name = [&](std::string& out, const char* what) {
    out.clear();
    for (int c; (c = std::fgetc(f.get())) != 0;) {
      if (c == EOF) throw InputError(path, 0, "cannot read EXR: the header ends inside an attribute");
      if (out.size() == max_name)
        throw InputError(path, 0,
                         std::string("cannot read EXR: an attribute ") + what + " longer than " +
                             std::to_string(max_name) + " bytes: '" + printable(out.substr(0, 40)) + "...'");
      out.push_back(char(c));
    }
  };
  std::string name, type;
  for (int headers = 0; headers < 1000000; ++headers) {
    bool empty_header = true;
    std::set<std::string> names;  // of this header
    int channels = 0;
    std::int64_t tile[2] = {0, 0};  // the `tiles` attribute's x and y size; 0: not tiled
    for (read_name(name, "name"); !name.empty(); read_name(name, "name")) {
      empty_header = false;
      unsigned char size_bytes[4];
      read_name(type, "type");
      if (std::fread(size_bytes, 1, 4, f.get()) != 4)
        throw InputError(path, 0, "cannot read EXR: the header ends inside an attribute");
      const long size =
          long(std::int32_t(std::uint32_t(size_bytes[0]) | std::uint32_t(size_bytes[1]) << 8 |
                            std::uint32_t(size_bytes[2]) << 16 | std::uint32_t(size_bytes[3]) << 24));
      const long left = file_size - std::ftell(f.get());
      if (size < 0 || size > left)
        throw InputError(path, 0,
                         "cannot read EXR: attribute '" + printable(name) + "' declares " +
                             std::to_string(size) + " bytes but the file holds only " + std::to_string(left) +
                             " more");
      const long expected = fixed_size(type);
      const long start = std::ftell(f.get());
      auto refuse = [&](const std::string& why) {
        return InputError(
            path, 0,
            "cannot read EXR: attribute '" + printable(name) + "' of type " + printable(type) + ": " + why);
      };
      if (!names.insert(name).second)
        throw refuse("given twice in one header (OpenEXR's two parsers would each read a different one)");
      if (expected >= 0 && size != expected)
        throw refuse("size " + std::to_string(size) + ", but this type has " + std::to_string(expected) +
                     " bytes");
      if (type == "chlist") {  // channels: name, 16 bytes each, until an empty name; must fill the value
        std::string channel;
        for (read_name(channel, "channel name"); !channel.empty(); read_name(channel, "channel name")) {
          std::fseek(f.get(), 16, SEEK_CUR);
          ++channels;
        }
        if (std::ftell(f.get()) != start + size)
          throw refuse("the channel list does not fill its " + std::to_string(size) + " bytes");
      } else if (type == "preview") {  // width, height, then width*height RGBA bytes
        unsigned char wh[8];
        if (size < 8 || std::fread(wh, 1, 8, f.get()) != 8) throw refuse("too short for a preview");
        auto u32 = [&](int i) {
          return std::uint64_t(wh[i]) | std::uint64_t(wh[i + 1]) << 8 | std::uint64_t(wh[i + 2]) << 16 |
                 std::uint64_t(wh[i + 3]) << 24;
        };
        if (8 + 4 * u32(0) * u32(4) != std::uint64_t(size))
          throw refuse("the preview size does not match its bytes");
      } else if (type == "tiledesc" && name == "tiles") {  // x size, y size (uint32), level mode
        unsigned char xy[8];
        if (std::fread(xy, 1, 8, f.get()) != 8) throw refuse("too short for a tile description");
        for (int a = 0; a < 2; ++a)
          tile[a] = std::int64_t(std::uint32_t(xy[4 * a]) | std::uint32_t(xy[4 * a + 1]) << 8 |
                                 std::uint32_t(xy[4 * a + 2]) << 16 | std::uint32_t(xy[4 * a + 3]) << 24);
        if (tile[0] == 0 || tile[1] == 0) throw refuse("a tile of no pixels");
      }
      std::fseek(f.get(), start + size, SEEK_SET);
    }
    if (tile[0] > 0) check_declared_tile_size(path, tile[0], tile[1], channels > 0 ? channels : 1);
    if (!multipart || empty_header) return;
  }
}

bool has_exr_magic(const unsigned char* bytes, std::size_t size) {
  return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

}  // namespace rayvec
