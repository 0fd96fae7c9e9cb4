// The only file that includes libpng. libpng reports errors by longjmp: every function here that
// calls into it sets the jump point first and holds no object with a destructor across the call,
// so a jump skips nothing; the C++ side throws once libpng has returned.
#include "image/png_file.h"

#include <png.h>
#include <sys/stat.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include "image/image_budget.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

struct PngContext {
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::FILE* file = nullptr;
  char error[200] = "";
};

extern "C" void on_png_error(png_structp png, png_const_charp message) {
  auto* ctx = static_cast<PngContext*>(png_get_error_ptr(png));
  std::snprintf(ctx->error, sizeof ctx->error, "%s", message);
  png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp, png_const_charp) {}

struct ReadHeader {
  png_uint_32 width = 0, height = 0;
  int channels = 0, bit_depth = 0;
  std::size_t rowbytes = 0;
};

// Header and the transformations to 8/16-bit Y, YA, RGB or RGBA; false with ctx.error on failure.
bool read_header(PngContext& ctx, ReadHeader& h) {
  if (setjmp(png_jmpbuf(ctx.png))) return false;
  png_init_io(ctx.png, ctx.file);
  png_read_info(ctx.png, ctx.info);
  const int colour = png_get_color_type(ctx.png, ctx.info);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(ctx.png);
  if (colour == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(ctx.png, ctx.info) < 8)
    png_set_expand_gray_1_2_4_to_8(ctx.png);
  if (png_get_valid(ctx.png, ctx.info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(ctx.png);
  if (png_get_bit_depth(ctx.png, ctx.info) == 16) png_set_swap(ctx.png);  // host order (little-endian)
  png_set_interlace_handling(ctx.png);
  png_read_update_info(ctx.png, ctx.info);
  h.width = png_get_image_width(ctx.png, ctx.info);
  h.height = png_get_image_height(ctx.png, ctx.info);
  h.channels = png_get_channels(ctx.png, ctx.info);
  h.bit_depth = png_get_bit_depth(ctx.png, ctx.info);
  h.rowbytes = png_get_rowbytes(ctx.png, ctx.info);
  return true;
}

bool read_rows(PngContext& ctx, png_bytepp rows) {
  if (setjmp(png_jmpbuf(ctx.png))) return false;
  png_read_image(ctx.png, rows);
  png_read_end(ctx.png, nullptr);
  return true;
}

// Walks the chunk list (length, type, data, CRC) and throws when a chunk claims more bytes than the
// file holds: libpng allocates an ancillary chunk (tEXt, iCCP, ...) at its declared length before
// reading it, so one corrupt length field in a small file would cost gigabytes.
void check_chunk_lengths(const std::string& path, std::FILE* file) {
  std::fseek(file, 0, SEEK_END);
  const long file_size = std::ftell(file);
  long at = 8;
  unsigned char head[8];
  while (at + 8 <= file_size) {
    std::fseek(file, at, SEEK_SET);
    if (std::fread(head, 1, 8, file) != 8) break;
    const long length = long(std::uint32_t(head[0]) << 24 | std::uint32_t(head[1]) << 16 |
                             std::uint32_t(head[2]) << 8 | std::uint32_t(head[3]));
    const long left = file_size - at - 12;
    if (length > left) {
      std::string type;
      for (int i = 4; i < 8; ++i) type += (head[i] >= 0x20 && head[i] < 0x7f) ? char(head[i]) : '?';
      throw InputError(path, 0,
                       "cannot read PNG: chunk '" + type + "' declares " + std::to_string(length) +
                           " bytes but the file holds only " + std::to_string(left < 0 ? 0 : left) + " more");
    }
    if (std::memcmp(head + 4, "IEND", 4) == 0) break;
    at += 12 + length;
  }
  std::fseek(file, 0, SEEK_SET);
}

}  // namespace

bool has_png_signature(const unsigned char* bytes, std::size_t size) {
  return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0;
}

ImageBytes read_png_bytes(const std::string& path) {
  PngContext ctx;
  ctx.file = std::fopen(path.c_str(), "rb");
  if (!ctx.file) throw InputError(path, 0, std::string("cannot read image: ") + std::strerror(errno));
  struct Cleanup {
    PngContext& c;
    ~Cleanup() {
      if (c.png) png_destroy_read_struct(&c.png, c.info ? &c.info : nullptr, nullptr);
      std::fclose(c.file);
    }
  } cleanup{ctx};
  check_chunk_lengths(path, ctx.file);
  ctx.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
  if (ctx.png) ctx.info = png_create_info_struct(ctx.png);
  if (!ctx.png || !ctx.info) throw RuntimeError(path + ": cannot read PNG: out of memory");
  ReadHeader h;
  if (!read_header(ctx, h)) throw InputError(path, 0, std::string("cannot read PNG: ") + ctx.error);
  check_declared_image_size(path, h.width, h.height, h.channels);
  struct stat st {};
  if (fstat(fileno(ctx.file), &st) == 0 && S_ISREG(st.st_mode))
    check_deflate_ratio(path, h.width, h.height, h.rowbytes * h.height, std::size_t(st.st_size));

  ImageBytes raw;
  raw.width = int(h.width);
  raw.height = int(h.height);
  raw.channels = h.channels;
  raw.bits = h.bit_depth == 16 ? 16 : 8;
  raw.bytes.resize(h.rowbytes * h.height);
  std::vector<png_bytep> rows(h.height);
  for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = raw.bytes.data() + std::size_t(y) * h.rowbytes;
  if (!read_rows(ctx, rows.data())) throw InputError(path, 0, std::string("cannot read PNG: ") + ctx.error);
  return raw;
}

Image read_png(const std::string& path, bool* sixteen_bit) {
  const ImageBytes raw = read_png_bytes(path);
  if (sixteen_bit) *sixteen_bit = raw.bits == 16;
  return image_of_bytes(raw);
}

}  // namespace rayvec
