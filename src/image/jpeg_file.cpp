// The only file that includes libjpeg. libjpeg reports errors through error_exit, which must not
// return: here it longjmps back to the function that called into libjpeg. Every such function sets
// the jump point first and holds no object with a destructor across the call, so a jump skips
// nothing; the C++ side throws once libjpeg has returned.
#include "image/jpeg_file.h"

#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

// jpeglib.h needs size_t and FILE declared before it
#include <jerror.h>
#include <jpeglib.h>

#include "image/image_budget.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

struct JpegErrors {
  jpeg_error_mgr pub;  // first: libjpeg sees a pointer to it
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = "";
  bool truncated = false;
};

struct JpegContext {
  jpeg_decompress_struct info{};
  JpegErrors errors{};
  jpeg_progress_mgr progress{};
  std::FILE* file = nullptr;
  bool created = false;
};

extern "C" void on_jpeg_error(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  errors->pub.format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}

// Warnings (level −1) let decoding go on; a file cut short is one that libjpeg would finish with
// grey, which is recorded and refused afterwards. Trace messages (levels ≥ 0) are dropped.
extern "C" void on_jpeg_message(j_common_ptr info, int level) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  if (level < 0 && errors->pub.msg_code == JWRN_JPEG_EOF) errors->truncated = true;
}

// Called between scans and passes: stops a progressive file with too many scans.
extern "C" void on_jpeg_progress(j_common_ptr info) {
  auto* d = reinterpret_cast<j_decompress_ptr>(info);
  if (d->progressive_mode && d->input_scan_number > kMaxJpegScans) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    std::snprintf(errors->message, sizeof errors->message, "more than %d progressive scans", kMaxJpegScans);
    std::longjmp(errors->jump, 1);
  }
}

bool read_header(JpegContext& ctx) {
  if (setjmp(ctx.errors.jump)) return false;
  jpeg_create_decompress(&ctx.info);
  ctx.created = true;
  ctx.progress.progress_monitor = on_jpeg_progress;
  ctx.info.progress = &ctx.progress;
  jpeg_stdio_src(&ctx.info, ctx.file);
  jpeg_read_header(&ctx.info, TRUE);
  return true;
}

// Decodes every scanline into `out` (rows of width · components bytes, top row first).
bool decode(JpegContext& ctx, std::uint8_t* out, std::size_t row_bytes) {
  if (setjmp(ctx.errors.jump)) return false;
  jpeg_start_decompress(&ctx.info);
  while (ctx.info.output_scanline < ctx.info.output_height) {
    JSAMPROW row = out + std::size_t(ctx.info.output_scanline) * row_bytes;
    jpeg_read_scanlines(&ctx.info, &row, 1);
  }
  jpeg_finish_decompress(&ctx.info);
  return true;
}

}  // namespace

bool has_jpeg_signature(const unsigned char* bytes, std::size_t size) {
  return size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

std::optional<ImageBytes> read_jpeg_bytes(const std::string& path) {
  JpegContext ctx;
  ctx.file = std::fopen(path.c_str(), "rb");
  if (!ctx.file) throw InputError(path, 0, std::string("cannot read image: ") + std::strerror(errno));
  struct Cleanup {
    JpegContext& c;
    ~Cleanup() {
      if (c.created) jpeg_destroy_decompress(&c.info);
      std::fclose(c.file);
    }
  } cleanup{ctx};
  ctx.info.err = jpeg_std_error(&ctx.errors.pub);
  ctx.errors.pub.error_exit = on_jpeg_error;
  ctx.errors.pub.emit_message = on_jpeg_message;
  if (!read_header(ctx)) throw InputError(path, 0, std::string("cannot read JPEG: ") + ctx.errors.message);

  int channels = 0;
  switch (ctx.info.jpeg_color_space) {
    case JCS_GRAYSCALE: channels = 1; break;
    case JCS_YCbCr:
    case JCS_RGB: channels = 3; break;
    default: return std::nullopt;  // CMYK, YCCK, unknown: OpenImageIO's conversions
  }
  if (ctx.info.num_components != channels) return std::nullopt;
  ctx.info.out_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
  check_declared_image_size(path, ctx.info.image_width, ctx.info.image_height, channels);

  ImageBytes raw;
  raw.width = int(ctx.info.image_width);
  raw.height = int(ctx.info.image_height);
  raw.channels = channels;
  const std::size_t row_bytes = std::size_t(raw.width) * std::size_t(channels);
  raw.bytes.resize(row_bytes * std::size_t(raw.height));
  if (!decode(ctx, raw.bytes.data(), row_bytes))
    throw InputError(path, 0, std::string("cannot read JPEG: ") + ctx.errors.message);
  if (ctx.errors.truncated)
    throw InputError(path, 0, "cannot read JPEG: the file ends before its image data does (truncated?)");

  return raw;
}

std::optional<Image> read_jpeg(const std::string& path) {
  if (std::optional<ImageBytes> raw = read_jpeg_bytes(path)) return image_of_bytes(*raw);
  return std::nullopt;
}

}  // namespace rayvec
