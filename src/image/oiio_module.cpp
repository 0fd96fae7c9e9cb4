// Loads librayvec_oiio.so on first use (see oiio_module_abi.h for why it is a module).
#include "image/oiio_module.h"

#include <mutex>
#include <string>

#include "image/image_budget.h"
#include "image/oiio_module_abi.h"
#include "io/input_error.h"
#include "platform/plugin.h"

namespace rayvec {
namespace {

struct Module {
  void* handle = nullptr;
  RayvecOiioOpenFn open = nullptr;
  RayvecOiioChannelFn channel = nullptr;
  RayvecOiioReadFn read = nullptr;
  RayvecOiioCloseFn close = nullptr;
  std::string error;  // why it could not be loaded
};

Module load() {
  Module m;
  const Plugin p = open_plugin("RAYVEC_OIIO_MODULE", kOiioModuleName, /*global=*/false);
  m.handle = p.handle;
  if (!p.handle) {
    m.error = plugin_problem(p, kOiioModuleName, "RAYVEC_OIIO_MODULE");
    return m;
  }
  auto abi = reinterpret_cast<RayvecOiioAbiFn>(plugin_symbol(p, "rayvec_oiio_abi"));
  m.open = reinterpret_cast<RayvecOiioOpenFn>(plugin_symbol(p, "rayvec_oiio_open"));
  m.channel = reinterpret_cast<RayvecOiioChannelFn>(plugin_symbol(p, "rayvec_oiio_channel"));
  m.read = reinterpret_cast<RayvecOiioReadFn>(plugin_symbol(p, "rayvec_oiio_read"));
  m.close = reinterpret_cast<RayvecOiioCloseFn>(plugin_symbol(p, "rayvec_oiio_close"));
  if (!abi || abi() != kRayvecOiioAbi || !m.open || !m.channel || !m.read || !m.close) {
    m.error = p.path + " is not a rayvec " + RAYVEC_VERSION + " image module (rebuild rayvec)";
    m.open = nullptr;
  }
  return m;
}

std::once_flag loaded_once;
Module* loaded = nullptr;

const Module& module() {
  std::call_once(loaded_once, [] { loaded = new Module(load()); });
  return *loaded;
}

}  // namespace

bool oiio_module_loaded() { return loaded && loaded->handle; }

Image read_with_oiio_module(const std::string& path, bool* encoded) {
  const Module& m = module();
  if (!m.open)
    throw RuntimeError(path + ": reading this format needs OpenImageIO through " + kOiioModuleName + ": " +
                       m.error);
  char error[512] = "";
  RayvecOiioInfo info{};
  void* in = m.open(path.c_str(), &info, error, sizeof error);
  if (!in) throw InputError(path, 0, std::string("cannot read image: ") + error);
  struct Closer {
    const Module& m;
    void* in;
    ~Closer() { m.close(in); }
  } closer{m, in};
  check_declared_image_size(path, info.width, info.height, info.channels);
  Image image;
  image.width = info.width;
  image.height = info.height;
  for (int c = 0; c < info.channels; ++c) image.channels.emplace_back(m.channel(in, c));
  image.pixels.resize(std::size_t(info.width) * std::size_t(info.height) * std::size_t(info.channels));
  if (!m.read(in, image.pixels.data(), error, sizeof error))
    throw InputError(path, 0, std::string("cannot read image: ") + error);
  if (encoded) *encoded = info.encoded != 0;
  return image;
}

}  // namespace rayvec
