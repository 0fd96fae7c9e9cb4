// Loads librayvec_oiio.so on first use (see oiio_module_abi.h for why it is a module).
#include "image/oiio_module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "image/image_budget.h"
#include "image/oiio_module_abi.h"
#include "io/input_error.h"

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

std::vector<std::string> candidate_paths() {
  std::vector<std::string> paths;
  if (const char* env = std::getenv("RAYVEC_OIIO_MODULE"); env && *env)
    return {env};  // the user's choice only
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / kOiioModuleName).string());
#ifdef RAYVEC_OIIO_MODULE_DIR
  paths.push_back(std::string(RAYVEC_OIIO_MODULE_DIR) + "/" + kOiioModuleName);
#endif
  return paths;
}

Module load() {
  Module m;
  std::string tried;
  for (const std::string& path : candidate_paths()) {
    tried += (tried.empty() ? "" : ", ") + path;
    if (::access(path.c_str(), F_OK) != 0) continue;
    m.handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!m.handle) {
      m.error = "cannot load " + path + ": " + ::dlerror();
      return m;
    }
    auto abi = reinterpret_cast<RayvecOiioAbiFn>(::dlsym(m.handle, "rayvec_oiio_abi"));
    m.open = reinterpret_cast<RayvecOiioOpenFn>(::dlsym(m.handle, "rayvec_oiio_open"));
    m.channel = reinterpret_cast<RayvecOiioChannelFn>(::dlsym(m.handle, "rayvec_oiio_channel"));
    m.read = reinterpret_cast<RayvecOiioReadFn>(::dlsym(m.handle, "rayvec_oiio_read"));
    m.close = reinterpret_cast<RayvecOiioCloseFn>(::dlsym(m.handle, "rayvec_oiio_close"));
    if (!abi || abi() != kRayvecOiioAbi || !m.open || !m.channel || !m.read || !m.close) {
      m.error = path + " is not a rayvec " + RAYVEC_VERSION + " image module (rebuild rayvec)";
      m.open = nullptr;
    }
    return m;
  }
  m.error = std::string(kOiioModuleName) + " not found (looked for " + tried +
            "); it is built beside the rayvec binary, or set RAYVEC_OIIO_MODULE to its path";
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
