// The only file that includes OpenImageIO. Writes go through an in-memory IOProxy and then
// AtomicFile, so OIIO never creates the final file itself and an interrupted render leaves nothing.
#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

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

// 8-bit sRGB bytes for a PNG: encode, clamp, round to nearest (no dither, so output is repeatable).
std::vector<uint8_t> encode_png_pixels(const Image& image) {
  std::vector<uint8_t> bytes(std::size_t(image.width) * image.height * 3);
  const int n = image.nchannels();
  for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
    for (int c = 0; c < 3; ++c) {
      const float v = c < n ? image.pixels[p * n + c] : 0.0f;
      const float e = std::isnan(v) ? 0.0f : std::clamp(srgb_encode(v), 0.0f, 1.0f);
      bytes[p * 3 + c] = static_cast<uint8_t>(std::lround(e * 255.0f));
    }
  return bytes;
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
  const bool png = lower_extension(path) == ".png";

  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out) throw RuntimeError("cannot write " + path + ": " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw RuntimeError("cannot write " + path + ": this OpenImageIO cannot write it to memory");

  OIIO::ImageSpec spec(image.width, image.height, png ? 3 : image.nchannels(),
                       png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (png) {
    spec.channelnames = {"R", "G", "B"};
    spec.attribute("oiio:ColorSpace", "sRGB");
  } else {
    spec.channelnames = image.channels;
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("compression", "zip");
    // Keep the channel order we give (R G B first); EXR readers sort by name anyway.
  }
  spec.attribute("Software", std::string("rayvec ") + RAYVEC_VERSION);
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  OIIO::Filesystem::IOVecOutput memory;
  out->set_ioproxy(&memory);
  bool ok = out->open(path, spec);
  if (ok) {
    if (png) {
      const std::vector<uint8_t> bytes = encode_png_pixels(image);
      ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
      ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
  }
  ok = out->close() && ok;
  if (!ok) throw RuntimeError("cannot write " + path + ": " + out->geterror());

  AtomicFile file(path);
  const auto& bytes = memory.buffer();
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size())
    throw RuntimeError("cannot write " + path + ": short write");
  file.commit();
}

Image read_image(const std::string& path) {
  std::error_code ec;  // not the throwing form: a name too long for the file system is bad input
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path, 0,
                     ec && ec != std::errc::no_such_file_or_directory ? "cannot read image: " + ec.message()
                                                                      : std::string("no such image file"));
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, 0, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw InputError(path, 0, "image has no pixels");
  Image image(spec.width, spec.height, spec.channelnames);
  if (image.nchannels() != spec.nchannels) image.channels.resize(spec.nchannels, "?");
  image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw InputError(path, 0, "cannot read image: " + in->geterror());
  return image;
}

Image read_texture(const std::string& path) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, 0, "cannot read texture: " + OIIO::geterror());
  const bool encoded = in->spec().format.basetype == OIIO::TypeDesc::UINT8 ||
                       in->spec().format.basetype == OIIO::TypeDesc::UINT16;
  in.reset();
  const Image raw = read_image(path);
  Image rgb(raw.width, raw.height, {"R", "G", "B"});
  const int n = raw.nchannels();
  for (int y = 0; y < raw.height; ++y)
    for (int x = 0; x < raw.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = raw.at(x, y, n >= 3 ? c : 0);
        rgb.at(x, y, c) = encoded ? srgb_decode(v) : v;
      }
  return rgb;
}

}  // namespace rayvec
