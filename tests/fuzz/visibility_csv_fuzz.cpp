// Fuzzes the visibility inputs: the same bytes are read as verts.csv, and as meshes.csv both
// against the number of vertex rows just read and against a vertex count taken from the first
// byte (so the faces parser runs even when the text is not a valid vertex file). Only InputError
// may escape; every face returned must index an existing vertex.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/input_error.h"
#include "io/visibility_csv.h"

namespace {

void faces(std::string_view text, std::size_t vertex_count) {
  try {
    for (const auto& f : rayvec::parse_faces_csv(text, "meshes.csv", vertex_count))
      for (uint32_t i : f)
        if (i >= vertex_count) __builtin_trap();
  } catch (const rayvec::InputError&) {}
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    faces(text, rayvec::parse_verts_csv(text, "verts.csv").size());
  } catch (const rayvec::InputError&) {}
  faces(text, size ? data[0] : 0);
  return 0;
}
