// Fuzzes the OBJ/MTL path: check_obj_text + tinyobjloader + load_obj's conversion. The input is an
// OBJ file, optionally followed by a line `#--mtl--` and the text of m.mtl (which the OBJ can pull
// in with `mtllib m.mtl`). The only acceptable failure is InputError; any other exception, crash,
// sanitizer report or hang is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "io/input_error.h"
#include "scene/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSplit = "#--mtl--";
  const std::size_t split = input.find(kSplit);
  const std::string_view obj = input.substr(0, split);
  const std::string_view mtl =
      split == std::string_view::npos ? std::string_view() : input.substr(split + kSplit.size());
  rayvec::fuzz::write_scratch("m.mtl", mtl);
  const std::string path = rayvec::fuzz::write_scratch("m.obj", obj);
  try {
    const rayvec::ObjModel model = rayvec::load_obj(path);
    // What the loader promises: every triangle corner is a valid vertex index.
    for (const auto& t : model.mesh.triangles)
      for (uint32_t i : t)
        if (i >= model.mesh.positions.size()) __builtin_trap();
    if (model.triangle_material.size() != model.mesh.triangles.size()) __builtin_trap();
    // ... and every position is finite (obj_scan rejects nan/inf text that tinyobjloader reads).
    for (const rayvec::Vec3f& p : model.mesh.positions)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
  } catch (const rayvec::InputError& e) {
    // load_obj's own guards behind obj_scan: reaching them means the scan missed a bad face and
    // the user got a message without a line number.
    if (std::string_view(e.what()).find("after triangulation") != std::string_view::npos ||
        std::string_view(e.what()).find("tinyobjloader returned") != std::string_view::npos)
      __builtin_trap();
  }
  return 0;
}
