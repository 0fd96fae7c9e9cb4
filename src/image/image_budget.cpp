#include "image/image_budget.h"

#include <cstdio>

#include "io/input_error.h"
#include "io/text_file.h"

namespace rayvec {
namespace {

// DEFLATE's largest ratio is 1032:1 (a 258-byte match coded in about two bits); a little slack for
// the zlib and PNG framing a file also holds.
constexpr double kMaxDeflateRatio = 1100.0;

std::string size_text(std::int64_t width, std::int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

std::string megabytes(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f MB", bytes / 1e6);
  return buf;
}

// Throws when `need` bytes exceed the input limit: `what` says what takes them.
void check_limit(const std::string& path, const std::string& what, std::size_t need) {
  const std::size_t limit = max_input_bytes();
  if (need > limit)
    throw InputError(path, 0,
                     what + ", " + megabytes(double(need)) + " once decoded, more than the " +
                         std::to_string(limit / 1000000) +
                         " MB input limit; set RAYVEC_MAX_INPUT_MB to raise it (e.g. RAYVEC_MAX_INPUT_MB=" +
                         std::to_string(need / 1000000 + 1000) + ") if this really is the image you meant");
}

}  // namespace

std::size_t decoded_image_bytes(std::int64_t width, std::int64_t height, int channels) {
  if (width <= 0 || height <= 0 || channels <= 0) return 0;
  const double bytes = double(width) * double(height) * double(channels) * sizeof(float);
  return bytes >= 1.8e19 ? std::size_t(-1) : std::size_t(bytes);
}

void check_declared_image_size(const std::string& path, std::int64_t width, std::int64_t height,
                               int channels) {
  const std::string what =
      "declares a " + size_text(width, height) + " image with " + std::to_string(channels) + " channels";
  if (width <= 0 || height <= 0 || channels <= 0)
    throw InputError(path, 0, what + ": an image needs at least one pixel and one channel");
  check_limit(path, what, decoded_image_bytes(width, height, channels));
}

void check_declared_tile_size(const std::string& path, std::int64_t width, std::int64_t height,
                              int channels) {
  const std::string what = "declares tiles of " + size_text(width, height) + " pixels with " +
                           std::to_string(channels) + " channels";
  if (width <= 0 || height <= 0) throw InputError(path, 0, what + ": a tile needs at least one pixel");
  check_limit(path, what + " (a whole tile is decoded at once)",
              decoded_image_bytes(width, height, channels));
}

void check_texture_size(const std::string& path, std::int64_t width, std::int64_t height) {
  check_limit(path, "is a " + size_text(width, height) + " texture, counted as RGB floats",
              decoded_image_bytes(width, height, 3));
}

void check_deflate_ratio(const std::string& path, std::int64_t width, std::int64_t height,
                         std::size_t raw_bytes, std::size_t file_bytes) {
  if (double(raw_bytes) > kMaxDeflateRatio * double(file_bytes))
    throw InputError(path, 0,
                     "declares a " + size_text(width, height) + " image (" + megabytes(double(raw_bytes)) +
                         " of pixel data) but holds only " + std::to_string(file_bytes) +
                         " bytes, too few for any compressed form of it: the header is corrupt or the "
                         "file is truncated");
}

}  // namespace rayvec
