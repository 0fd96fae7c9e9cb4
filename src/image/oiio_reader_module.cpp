// librayvec_oiio.so: OpenImageIO's readers behind the C interface of oiio_module_abi.h. The only
// file that includes OpenImageIO; it is built as a module beside the rayvec binary and loaded by
// oiio_module.cpp on first use.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <string>

#include "image/oiio_module_abi.h"

namespace {

void set_error(char* error, std::size_t size, const std::string& text) {
  if (error && size) std::snprintf(error, size, "%s", text.c_str());
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int rayvec_oiio_abi() { return kRayvecOiioAbi; }

__attribute__((visibility("default"))) void* rayvec_oiio_open(const char* path, RayvecOiioInfo* info,
                                                              char* error, std::size_t error_size) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) {
    set_error(error, error_size, OIIO::geterror());
    return nullptr;
  }
  const OIIO::ImageSpec& spec = in->spec();
  info->width = spec.width;
  info->height = spec.height;
  info->channels = spec.nchannels;
  info->encoded =
      spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
  return in.release();
}

__attribute__((visibility("default"))) const char* rayvec_oiio_channel(void* handle, int c) {
  const auto* in = static_cast<OIIO::ImageInput*>(handle);
  const auto& names = in->spec().channelnames;
  return c >= 0 && std::size_t(c) < names.size() ? names[std::size_t(c)].c_str() : "?";
}

__attribute__((visibility("default"))) int rayvec_oiio_read(void* handle, float* pixels, char* error,
                                                            std::size_t error_size) {
  auto* in = static_cast<OIIO::ImageInput*>(handle);
  if (in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, pixels)) return 1;
  set_error(error, error_size, in->geterror());
  return 0;
}

__attribute__((visibility("default"))) void rayvec_oiio_close(void* handle) {
  delete static_cast<OIIO::ImageInput*>(handle);
}
}
