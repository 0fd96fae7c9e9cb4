// Fuzzes the PNG, JPEG and EXR readers (read_png through libpng; read_jpeg through libjpeg, called
// directly so that a CMYK file is not handed on to OpenImageIO; read_exr: the attribute walk, then
// OpenEXRCore's header parser and the OpenEXR C++ library in librayvec_exr.so, built instrumented
// beside the harness and loaded on the first EXR) and the declared-size checks in front of them. Inputs
// that start with none of the PNG signature, the JPEG marker and the EXR magic are skipped: other
// formats belong to OpenImageIO's module. The input limit is lowered to 4 MB so that a header declaring a
// large raster must be refused, not decoded. Only InputError may escape; an image that loads must hold width
// × height × channels pixels within that limit, a texture three codes or floats a texel.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "fuzz_support.h"
#include "image/exr_header.h"
#include "image/image_budget.h"
#include "image/image_io.h"
#include "image/jpeg_file.h"
#include "image/png_file.h"
#include "io/input_error.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ::setenv("RAYVEC_MAX_INPUT_MB", "4", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const bool jpeg = rayvec::has_jpeg_signature(data, size);
  if (!jpeg && !rayvec::has_png_signature(data, size) && !rayvec::has_exr_magic(data, size)) return 0;
  const std::string path =
      rayvec::fuzz::write_scratch("image.bin", std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    if (jpeg) {
      const std::optional<rayvec::Image> image = rayvec::read_jpeg(path);
      if (!image) return 0;  // CMYK and the like: OpenImageIO's
      if (image->width < 1 || image->height < 1 || (image->nchannels() != 1 && image->nchannels() != 3))
        __builtin_trap();
      if (image->pixels.size() !=
          std::size_t(image->width) * std::size_t(image->height) * image->channels.size())
        __builtin_trap();
      if (rayvec::decoded_image_bytes(image->width, image->height, image->nchannels()) > 4000000)
        __builtin_trap();
      return 0;
    }
    const rayvec::Texture texture = rayvec::read_texture(path);
    if (texture.width() < 1 || texture.height() < 1) __builtin_trap();
    const std::size_t texels = std::size_t(texture.width()) * std::size_t(texture.height());
    if (texture.bytes() != texels * (texture.holds_codes() ? 3 : 3 * sizeof(float))) __builtin_trap();
    if (rayvec::decoded_image_bytes(texture.width(), texture.height(), 3) > 4000000) __builtin_trap();
    const rayvec::Vec3f last = texture.texel(texture.width() - 1, texture.height() - 1);
    if (last.x != last.x && texture.holds_codes()) __builtin_trap();  // codes decode to numbers
  } catch (const rayvec::InputError&) {}
  return 0;
}
