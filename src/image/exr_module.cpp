// librayvec_exr.so: OpenEXR behind the C interface of exr_module_abi.h. The only file that includes
// OpenEXR (OpenEXRCore for the header, the C++ library for pixels); it is built as a module beside the
// rayvec binary and loaded by exr_file.cpp on first use. Every exception stops here and crosses as a
// status and a message.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/openexr.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "image/exr_module_abi.h"

namespace {

void set_error(char* error, std::size_t size, const char* text) {
  if (error && size) std::snprintf(error, size, "%s", text);
}

// OpenEXRCore reports errors to a callback (the default one prints to stderr); keep the last one.
struct ErrorText {
  char text[256] = "";
};

extern "C" void keep_exr_error(exr_const_context_t ctxt, exr_result_t code, const char* msg) {
  void* user = nullptr;
  if (ctxt && exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user)
    std::snprintf(static_cast<ErrorText*>(user)->text, sizeof ErrorText::text, "%s",
                  msg ? msg : exr_get_default_error_message(code));
}

struct File {
  std::string path;
  ErrorText why;                 // OpenEXRCore's last message about this file
  exr_context_t core = nullptr;  // OpenEXRCore's view of the file, open until close
  bool tiled = false;
  int min_x = 0, min_y = 0, width = 0, height = 0;
  std::vector<std::string> channels;      // every one sampled 1 in x and y
  std::unique_ptr<Imf::InputFile> input;  // built at the first read, once the caller accepted the size
  ~File() { exr_finish(&core); }
};

// The header through OpenEXRCore, which parses it alone and allocates nothing for the pixels.
int open_file(const char* path, void** out, RayvecExrInfo* info, char* error, std::size_t error_size) try {
  *out = nullptr;
  auto file = std::make_unique<File>();
  file->path = path;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_exr_error;
  init.user_data = &file->why;
  exr_storage_t storage{};
  exr_attr_box2i_t box{};
  const exr_attr_chlist_t* channels = nullptr;
  int parts = 0;
  exr_result_t rc = exr_start_read(&file->core, path, &init);
  if (rc == EXR_ERR_SUCCESS) rc = exr_get_count(file->core, &parts);
  if (rc == EXR_ERR_SUCCESS) rc = exr_get_storage(file->core, 0, &storage);
  if (rc == EXR_ERR_SUCCESS) rc = exr_get_data_window(file->core, 0, &box);
  if (rc == EXR_ERR_SUCCESS) rc = exr_get_channels(file->core, 0, &channels);
  if (rc != EXR_ERR_SUCCESS) {
    set_error(error, error_size, file->why.text[0] ? file->why.text : exr_get_default_error_message(rc));
    return kRayvecExrBadInput;
  }
  *info = RayvecExrInfo{};
  info->deep = storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED;
  file->tiled = storage == EXR_STORAGE_TILED;
  info->min_x = file->min_x = box.min.x;
  info->min_y = file->min_y = box.min.y;
  const long long w = (long long)box.max.x - box.min.x + 1, h = (long long)box.max.y - box.min.y + 1;
  info->width = file->width = w > 0 && w <= 0x7fffffff ? int(w) : 0;
  info->height = file->height = h > 0 && h <= 0x7fffffff ? int(h) : 0;
  for (int c = 0; channels && c < channels->num_channels; ++c) {
    const exr_attr_chlist_entry_t& e = channels->entries[c];
    file->channels.emplace_back(e.name.str, std::size_t(e.name.length));
    info->subsampled = info->subsampled || e.x_sampling != 1 || e.y_sampling != 1;
  }
  info->channels = int(file->channels.size());
  *out = file.release();
  return kRayvecExrOk;
} catch (const std::exception& e) {
  set_error(error, error_size, e.what());
  return kRayvecExrBadInput;
}

// Every chunk of the data window (level 0 of a tiled file) through OpenEXRCore, which checks its
// offset, its coordinates and that its packed bytes lie within the file. The C++ reader instead
// decodes a chunk cut off by the end of the file from a buffer it never filled, and reports success.
exr_result_t check_chunks(File& f) {
  exr_chunk_info_t chunk{};
  if (!f.tiled) {
    int32_t lines = 0;
    exr_result_t rc = exr_get_scanlines_per_chunk(f.core, 0, &lines);
    for (long long y = f.min_y; rc == EXR_ERR_SUCCESS && y < (long long)f.min_y + f.height; y += lines)
      rc = lines > 0 ? exr_read_scanline_chunk_info(f.core, 0, int(y), &chunk) : EXR_ERR_INVALID_ATTR;
    return rc;
  }
  int32_t tile_w = 0, tile_h = 0;
  exr_result_t rc = exr_get_tile_sizes(f.core, 0, 0, 0, &tile_w, &tile_h);
  if (rc != EXR_ERR_SUCCESS) return rc;
  if (tile_w <= 0 || tile_h <= 0) return EXR_ERR_INVALID_ATTR;
  const int tiles_x = int((f.width + (long long)tile_w - 1) / tile_w);
  const int tiles_y = int((f.height + (long long)tile_h - 1) / tile_h);
  for (int ty = 0; rc == EXR_ERR_SUCCESS && ty < tiles_y; ++ty)
    for (int tx = 0; rc == EXR_ERR_SUCCESS && tx < tiles_x; ++tx)
      rc = exr_read_tile_chunk_info(f.core, 0, tx, ty, 0, 0, &chunk);
  return rc;
}

const char* channel_name(void* file, int c) {
  const auto& names = static_cast<File*>(file)->channels;
  return c >= 0 && std::size_t(c) < names.size() ? names[std::size_t(c)].c_str() : "?";
}

// The C++ library parses the header again, on its own: where a malformed file reads differently to
// the two parsers (a repeated attribute, repeated channel names), its pixels would be written with a
// layout the caller's buffer was not sized for. Such a file is refused.
bool same_layout(const File& f, const Imf::Header& header) {
  const Imath::Box2i& box = header.dataWindow();
  if (box.min.x != f.min_x || box.min.y != f.min_y || (long long)box.max.x - box.min.x + 1 != f.width ||
      (long long)box.max.y - box.min.y + 1 != f.height)
    return false;
  std::size_t count = 0;
  for (auto c = header.channels().begin(); c != header.channels().end(); ++c, ++count) {
    if (c.channel().xSampling != 1 || c.channel().ySampling != 1) return false;
    if (std::find(f.channels.begin(), f.channels.end(), c.name()) == f.channels.end()) return false;
  }
  return count == f.channels.size();
}

int read_rows(void* handle, const char* const* names, int count, float* pixels, int y0, int y1, char* error,
              std::size_t error_size) try {
  File& f = *static_cast<File*>(handle);
  if (!f.input) {
    auto input = std::make_unique<Imf::InputFile>(f.path.c_str());
    if (!same_layout(f, input->header())) {
      set_error(error, error_size,
                "OpenEXR's two header parsers disagree on its data window or channels (a repeated "
                "attribute or channel name?); rewrite the file with a standard tool");
      return kRayvecExrBadInput;
    }
    f.why.text[0] = '\0';
    if (const exr_result_t rc = check_chunks(f); rc != EXR_ERR_SUCCESS) {
      const std::string why = f.why.text[0] ? f.why.text : exr_get_default_error_message(rc);
      set_error(error, error_size, ("pixel data: " + why).c_str());
      return kRayvecExrBadInput;
    }
    f.input = std::move(input);
  }
  const std::size_t nch = std::size_t(count);
  const std::size_t row_floats = std::size_t(f.width) * nch;
  // The slice addresses pixel (x, y) of the data window at base + x*xs + y*ys; point it at row 0.
  char* row0 = reinterpret_cast<char*>(pixels) - (std::ptrdiff_t(f.min_y) * std::ptrdiff_t(row_floats) +
                                                  std::ptrdiff_t(f.min_x) * std::ptrdiff_t(nch)) *
                                                     std::ptrdiff_t(sizeof(float));
  Imf::FrameBuffer fb;
  for (std::size_t c = 0; c < nch; ++c)
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, row0 + c * sizeof(float), nch * sizeof(float),
                                   row_floats * sizeof(float)));
  f.input->setFrameBuffer(fb);
  f.input->readPixels(f.min_y + y0, f.min_y + y1 - 1);
  return kRayvecExrOk;
} catch (const std::exception& e) {
  set_error(error, error_size, e.what());
  return kRayvecExrBadInput;
}

void close_file(void* file) { delete static_cast<File*>(file); }

// An output stream into the caller's buffer, grown through its callback.
class GrowingStream : public Imf::OStream {
 public:
  GrowingStream(RayvecExrGrowFn grow, void* user) : Imf::OStream("memory"), grow_(grow), user_(user) {}
  void write(const char c[], int n) override {
    if (pos_ + std::size_t(n) > size_) {
      data_ = grow_(user_, pos_ + std::size_t(n));
      if (!data_) throw std::bad_alloc();
      size_ = pos_ + std::size_t(n);
    }
    std::memcpy(data_ + pos_, c, std::size_t(n));
    pos_ += std::size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = std::size_t(pos); }
  std::size_t size() const { return size_; }

 private:
  RayvecExrGrowFn grow_;
  void* user_;
  unsigned char* data_ = nullptr;
  std::size_t size_ = 0;  // bytes written so far: the end of the furthest write
  std::size_t pos_ = 0;
};

int encode(int width, int height, const char* const* names, int count, const float* pixels,
           const char* const* keys, const char* const* values, int meta_count, RayvecExrGrowFn grow,
           void* user, std::size_t* size, char* error, std::size_t error_size) try {
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.zipCompressionLevel() = kRayvecExrZipLevel;
  const std::size_t nch = std::size_t(count);
  for (std::size_t c = 0; c < nch; ++c) header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
  header.insert("oiio:ColorSpace", Imf::StringAttribute("Linear"));
  for (int i = 0; i < meta_count; ++i) header.insert(keys[i], Imf::StringAttribute(values[i]));

  GrowingStream stream(grow, user);
  {
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(const_cast<float*>(pixels));
    for (std::size_t c = 0; c < nch; ++c)
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), nch * sizeof(float),
                                     std::size_t(width) * nch * sizeof(float)));
    file.setFrameBuffer(fb);
    file.writePixels(height);
  }  // the destructor writes the line offset table
  *size = stream.size();
  return kRayvecExrOk;
} catch (const std::exception& e) {
  set_error(error, error_size, e.what());
  return kRayvecExrFailed;
}

void set_threads(int threads) {
  const int workers = threads > 1 ? threads : 0;  // 0: the calling thread alone
  if (workers != Imf::globalThreadCount()) Imf::setGlobalThreadCount(workers);
}

constexpr RayvecExrModule kModule = {kRayvecExrAbi, open_file, channel_name, read_rows,
                                     close_file,    encode,    set_threads};

}  // namespace

extern "C" __attribute__((visibility("default"))) const RayvecExrModule* rayvec_exr_module() {
  return &kModule;
}
