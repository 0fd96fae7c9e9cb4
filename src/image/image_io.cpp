// Image files: PNG through libpng (png_file.cpp), JPEG through libjpeg (jpeg_file.cpp), EXR through
// OpenEXR in a module loaded only when an EXR is read or written (exr_file.cpp), every other format
// (and CMYK JPEGs) through OpenImageIO in a module loaded only when such a file is read
// (oiio_module.cpp).
// The format is told by the file's first bytes, not its name. Writes are encoded in memory and
// committed through AtomicFile, so an interrupted render leaves nothing.
#include "image/image_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

#include "image/exr_file.h"
#include "image/exr_header.h"
#include "image/image_budget.h"
#include "image/jpeg_file.h"
#include "image/oiio_module.h"
#include "image/png_encoder.h"
#include "image/png_file.h"
#include "image/srgb8.h"
#include "io/atomic_file.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The image as a PNG: 8-bit sRGB bytes (encode, clamp, round to nearest; no dither, so output is
// repeatable), by the table of srgb8.h rather than a pow() per channel, a row at a time on each of
// the encoder's threads.
std::vector<std::uint8_t> encode_png(const Image& image, const ImageMetadata& metadata) {
  const std::size_t row_floats = std::size_t(image.width) * std::size_t(image.nchannels());
  return encode_png_rgb8(
      image.width, image.height,
      [&](int y, std::uint8_t* row) {
        srgb8_pixels(image.pixels.data() + std::size_t(y) * row_floats, image.nchannels(),
                     std::size_t(image.width), row);
      },
      metadata);
}

enum class Format { png, jpeg, exr, other };

Format sniff(const std::string& path) {
  std::error_code ec;  // not the throwing form: a name too long for the file system is bad input
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path, 0,
                     ec && ec != std::errc::no_such_file_or_directory ? "cannot read image: " + ec.message()
                                                                      : std::string("no such image file"));
  unsigned char head[8] = {};
  std::size_t got = 0;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    got = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
  }
  if (has_png_signature(head, got)) return Format::png;
  if (has_jpeg_signature(head, got)) return Format::jpeg;
  if (has_exr_magic(head, got)) return Format::exr;
  return Format::other;
}

Image read_any(const std::string& path, Format format, bool* encoded) {
  switch (format) {
    case Format::png: *encoded = true; return read_png(path);
    case Format::exr: *encoded = false; return read_exr(path);
    case Format::jpeg:
      if (std::optional<Image> image = read_jpeg(path)) {
        *encoded = true;
        return std::move(*image);
      }
      break;
    case Format::other: break;
  }
  return read_with_oiio_module(path, encoded);
}

Texture texture_of(const std::string& path, const ImageBytes& raw) {
  check_texture_size(path, raw.width, raw.height);
  return Texture(raw);
}

}  // namespace

float srgb_encode(float x) {
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float x) { return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f); }

bool is_writable_image_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".png";
}

void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata) {
  if (!is_writable_image_path(path))
    throw InputError(path + ": unknown image extension '" + lower_extension(path) +
                     "' (write .png for 8-bit sRGB or .exr for linear float)");
  if (image.width <= 0 || image.height <= 0 || image.nchannels() < 3)
    throw RuntimeError("cannot write " + path + ": empty image");
  ImageMetadata meta{{"Software", std::string("rayvec ") + RAYVEC_VERSION}};
  meta.insert(meta.end(), metadata.begin(), metadata.end());
  std::vector<std::uint8_t> bytes;
  try {
    bytes = lower_extension(path) == ".png" ? encode_png(image, meta) : encode_exr(image, meta);
  } catch (const RuntimeError& e) {
    throw RuntimeError("cannot write " + path + ": " + e.what());
  }
  AtomicFile file(path);
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size())
    throw RuntimeError("cannot write " + path + ": short write");
  file.commit();
}

void require_image_writer(const std::string& path) {
  if (lower_extension(path) == ".exr") require_exr_module();
}

Image read_image(const std::string& path) {
  bool encoded = false;
  return read_any(path, sniff(path), &encoded);
}

Image read_image(const std::string& path, bool* encoded) {
  bool unused = false;
  return read_any(path, sniff(path), encoded ? encoded : &unused);
}

Texture read_texture(const std::string& path) {
  // 8-bit PNG and JPEG codes straight into the texture, without a float image in between
  const Format format = sniff(path);
  if (format == Format::png) return texture_of(path, read_png_bytes(path));
  if (format == Format::jpeg)
    if (std::optional<ImageBytes> raw = read_jpeg_bytes(path)) return texture_of(path, *raw);
  bool encoded = false;
  const Image raw = read_any(path, format, &encoded);
  check_texture_size(path, raw.width, raw.height);
  return Texture(raw, encoded);
}

}  // namespace rayvec
