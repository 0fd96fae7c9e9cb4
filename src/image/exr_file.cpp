// EXR through librayvec_exr.so (exr_module_abi.h says why it is a module): loads it on first use,
// drives its two-phase read (header, then the caller's size checks and buffer, then pixels a strip at a
// time) and turns its status and message back into rayvec's errors. Writes come back as bytes that
// the caller commits through AtomicFile.
#include "image/exr_file.h"

#if defined(_OPENMP)
#include <omp.h>
#endif

#include <algorithm>
#include <exception>
#include <mutex>
#include <new>

#include "image/exr_header.h"
#include "image/exr_module_abi.h"
#include "image/image_budget.h"
#include "io/input_error.h"
#include "platform/plugin.h"

namespace rayvec {
namespace {

constexpr int kStripRows = 64;  // scanlines decoded per read_rows call
constexpr std::size_t kErrorSize = 8192;

struct Module {
  const RayvecExrModule* table = nullptr;  // null when it could not be loaded
  std::string error;                       // why
};

Module load() {
  Module m;
  const Plugin p = open_plugin("RAYVEC_EXR_MODULE", kExrModuleName, /*global=*/false);
  if (!p.handle) {
    m.error = plugin_problem(p, kExrModuleName, "RAYVEC_EXR_MODULE");
    return m;
  }
  const auto entry = reinterpret_cast<RayvecExrModuleFn>(plugin_symbol(p, "rayvec_exr_module"));
  const RayvecExrModule* table = entry ? entry() : nullptr;
  if (!table || table->abi != kRayvecExrAbi || !table->open || !table->channel || !table->read_rows ||
      !table->close || !table->encode || !table->set_threads)
    m.error = p.path + " is not a rayvec " + RAYVEC_VERSION + " EXR module (rebuild rayvec)";
  else
    m.table = table;
  return m;
}

std::once_flag loaded_once;
Module* loaded = nullptr;

// The module, its line blocks (de)compressed on as many threads as the command may use.
const RayvecExrModule& module(const std::string& what) {
  std::call_once(loaded_once, [] { loaded = new Module(load()); });
  if (!loaded->table)
    throw RuntimeError(what + " needs OpenEXR through " + kExrModuleName + ": " + loaded->error);
#if defined(_OPENMP)
  loaded->table->set_threads(omp_get_max_threads());
#else
  loaded->table->set_threads(1);  // a build without OpenMP (the fuzzers'): the caller alone
#endif
  return *loaded->table;
}

// OpenImageIO's order: within a layer R G B A Z first; the unlayered channels before any layer.
int rank_in_layer(const std::string& base) {
  static const char* const kFirst[] = {"R", "G", "B", "A", "Z"};
  for (int i = 0; i < 5; ++i)
    if (base == kFirst[i]) return i;
  return 5;
}

std::vector<std::string> oiio_order(std::vector<std::string> names) {
  auto split = [](const std::string& n) {
    const auto dot = n.rfind('.');
    return dot == std::string::npos
               ? std::pair<std::string, std::string>{"", n}
               : std::pair<std::string, std::string>{n.substr(0, dot), n.substr(dot + 1)};
  };
  std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
    const auto [la, ba] = split(a);
    const auto [lb, bb] = split(b);
    if (la != lb) return la < lb;  // "" (no layer) sorts first
    return rank_in_layer(ba) < rank_in_layer(bb);
  });
  return names;
}

std::vector<const char*> c_strings(const std::vector<std::string>& strings) {
  std::vector<const char*> out;
  for (const std::string& s : strings) out.push_back(s.c_str());
  return out;
}

}  // namespace

void require_exr_module() { module("writing EXR"); }

Image read_exr(const std::string& path) {
  const RayvecExrModule& m = module(path + ": reading EXR");
  check_exr_attributes(path);
  std::string error(kErrorSize, '\0');
  auto why = [&] { return std::string("cannot read EXR: ") + error.c_str(); };
  RayvecExrInfo h{};
  void* file = nullptr;
  if (m.open(path.c_str(), &file, &h, error.data(), error.size()) != kRayvecExrOk)
    throw InputError(path, 0, why());
  struct Closer {
    const RayvecExrModule& m;
    void* file;
    ~Closer() { m.close(file); }
  } closer{m, file};
  if (h.deep) throw InputError(path, 0, "cannot read EXR: deep images are not supported");
  if (h.subsampled) throw InputError(path, 0, "cannot read EXR: subsampled channels are not supported");
  check_declared_image_size(path, h.width, h.height, h.channels);

  Image image;
  image.width = h.width;
  image.height = h.height;
  for (int c = 0; c < h.channels; ++c) image.channels.emplace_back(m.channel(file, c));
  image.channels = oiio_order(std::move(image.channels));
  const std::vector<const char*> names = c_strings(image.channels);
  const std::size_t row_floats = std::size_t(h.width) * names.size();
  try {
    for (int y0 = 0; y0 < h.height; y0 += kStripRows) {
      const int y1 = std::min(h.height, y0 + kStripRows);  // rows [y0, y1) of the data window
      image.pixels.resize(std::size_t(y1) * row_floats);
      if (m.read_rows(file, names.data(), int(names.size()), image.pixels.data(), y0, y1, error.data(),
                      error.size()) != kRayvecExrOk)
        throw InputError(path, 0, why());
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, 0, std::string("cannot read EXR: ") + e.what());
  }
  return image;
}

std::vector<std::uint8_t> encode_exr(const Image& image, const ImageMetadata& metadata) {
  const RayvecExrModule& m = module("writing EXR");
  const std::vector<const char*> names = c_strings(image.channels);
  std::vector<const char*> keys, values;
  for (const auto& [key, value] : metadata) {
    keys.push_back(key.c_str());
    values.push_back(value.c_str());
  }
  // room for the uncompressed pixels and the tables up front: grown by the writes, the buffer was
  // reallocated and copied at every doubling
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixels.size() * sizeof(float) + std::size_t(image.height) * 16 + 65536);
  auto grow = [](void* user, std::size_t size) noexcept -> unsigned char* {
    auto& v = *static_cast<std::vector<std::uint8_t>*>(user);
    try {
      v.resize(size);
    } catch (const std::bad_alloc&) {
      return nullptr;
    }
    return v.data();
  };
  std::size_t size = 0;
  std::string error(kErrorSize, '\0');
  if (m.encode(image.width, image.height, names.data(), int(names.size()), image.pixels.data(), keys.data(),
               values.data(), int(keys.size()), grow, &bytes, &size, error.data(),
               error.size()) != kRayvecExrOk)
    throw RuntimeError(std::string("cannot encode EXR: ") + error.c_str());
  bytes.resize(size);
  return bytes;
}

}  // namespace rayvec
