// Fuzzes the MTL path through rayvec's OBJ loader: the input is the text of m.mtl, pulled in by a
// fixed OBJ that uses two of its materials (`a`, `b`) and one it may not define. load_obj reads the
// MTL through read_mtl_file (rayvec's MTL parser, its validation and the texture look-up) while
// tinyobjloader numbers the `usemtl` names. The only acceptable failure is InputError; any other
// exception, crash, sanitizer report or hang is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "io/input_error.h"
#include "scene/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const std::string obj = rayvec::fuzz::write_scratch(
      "mtl_fuzz.obj",
      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\nusemtl zz\nf 2 3 1\n");
  rayvec::fuzz::write_scratch("m.mtl", std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    const rayvec::ObjModel model = rayvec::load_obj(obj);
    // What the loader promises: one material slot per triangle, each -1 or a valid material.
    if (model.triangle_material.size() != model.mesh.triangles.size()) __builtin_trap();
    for (int32_t m : model.triangle_material)
      if (m < -1 || m >= static_cast<int32_t>(model.materials.size())) __builtin_trap();
  } catch (const rayvec::InputError&) {}
  return 0;
}
