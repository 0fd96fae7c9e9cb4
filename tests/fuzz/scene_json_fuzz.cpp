// Fuzzes the JSON scene loader (load_scene_json). The input is written as scene.json next to a
// small valid model m.obj (with m.mtl) that scenes can name as {"obj": "m.obj"}. Only InputError
// may escape; a loaded scene must have a camera of 1..16384 pixels a side and per-triangle arrays
// of the mesh's size.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "io/input_error.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const bool model_written = [] {
    rayvec::fuzz::write_scratch("m.mtl", "newmtl red\nKd 0.8 0.1 0.1\nKs 0.2 0.2 0.2\nNs 20\n");
    rayvec::fuzz::write_scratch("m.obj",
                                "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nusemtl red\nf 1/1/1 2/2/1 3/3/1 4/1/1\n");
    return true;
  }();
  (void)model_written;
  const std::string path =
      rayvec::fuzz::write_scratch("scene.json", std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    const rayvec::Scene scene = rayvec::load_scene_json(path);
    const auto& c = scene.camera;
    if (c.width < 1 || c.width > 16384 || c.height < 1 || c.height > 16384) __builtin_trap();
    if (scene.triangle_material.size() != scene.mesh.size()) __builtin_trap();
  } catch (const rayvec::InputError&) {}
  return 0;
}
