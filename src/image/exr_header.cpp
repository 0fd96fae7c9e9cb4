// The only file that includes OpenEXRCore. Its errors go to a callback that keeps the last message
// (the default one prints to stderr), and the message is thrown once the library has returned.
#include "image/exr_header.h"

#include <OpenEXR/openexr.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <utility>

#include "io/input_error.h"

namespace rayvec {
namespace {

struct ErrorText {
  char text[256] = "";
};

extern "C" void keep_exr_error(exr_const_context_t ctxt, exr_result_t code, const char* msg) {
  void* user = nullptr;
  if (ctxt && exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user)
    std::snprintf(static_cast<ErrorText*>(user)->text, sizeof ErrorText::text, "%s",
                  msg ? msg : exr_get_default_error_message(code));
}

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

// Walks the attribute list of every header (name, type, int32 size, value) and throws when a value
// claims more bytes than the file holds or a size the C++ reader would not consume. That reader
// allocates an attribute of unknown type at its declared size before reading it, reads a typed one
// by its own layout whatever the size field says (and then parses the rest of the header out of
// step), and allocates a preview at width x height x 4: one corrupt field in a small file would
// cost gigabytes. OpenEXRCore skips such values unread and so does not catch it.
void check_attribute_sizes(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return;  // exr_start_read reports it
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
      if (expected >= 0 && size != expected)
        throw refuse("size " + std::to_string(size) + ", but this type has " + std::to_string(expected) +
                     " bytes");
      if (type == "chlist") {  // channels: name, 16 bytes each, until an empty name; must fill the value
        std::string channel;
        for (read_name(channel, "channel name"); !channel.empty(); read_name(channel, "channel name"))
          std::fseek(f.get(), 16, SEEK_CUR);
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
      }
      std::fseek(f.get(), start + size, SEEK_SET);
    }
    if (!multipart || empty_header) return;
  }
}

}  // namespace

bool has_exr_magic(const unsigned char* bytes, std::size_t size) {
  return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

ExrHeader read_exr_header(const std::string& path) {
  check_attribute_sizes(path);
  ErrorText error;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_exr_error;
  init.user_data = &error;
  exr_context_t ctxt = nullptr;
  exr_result_t rc = exr_start_read(&ctxt, path.c_str(), &init);
  auto fail = [&](exr_result_t code) {
    const std::string why = error.text[0] ? error.text : exr_get_default_error_message(code);
    exr_finish(&ctxt);
    return InputError(path, 0, "cannot read EXR: " + why);
  };
  if (rc != EXR_ERR_SUCCESS) throw fail(rc);
  ExrHeader h;
  exr_storage_t storage{};
  exr_attr_box2i_t box{};
  const exr_attr_chlist_t* channels = nullptr;
  if ((rc = exr_get_count(ctxt, &h.parts)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_storage(ctxt, 0, &storage)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_data_window(ctxt, 0, &box)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_channels(ctxt, 0, &channels)) != EXR_ERR_SUCCESS)
    throw fail(rc);
  h.deep = storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED;
  h.min_x = box.min.x;
  h.min_y = box.min.y;
  const long long w = (long long)box.max.x - box.min.x + 1, ht = (long long)box.max.y - box.min.y + 1;
  h.width = w > 0 && w <= 0x7fffffff ? int(w) : 0;
  h.height = ht > 0 && ht <= 0x7fffffff ? int(ht) : 0;
  for (int c = 0; channels && c < channels->num_channels; ++c) {
    const exr_attr_chlist_entry_t& e = channels->entries[c];
    h.channels.emplace_back(e.name.str, std::size_t(e.name.length));
    h.subsampled = h.subsampled || e.x_sampling != 1 || e.y_sampling != 1;
  }
  exr_finish(&ctxt);
  return h;
}

}  // namespace rayvec
