// The ray tree of one pixel sample (render/ray_tree.h) as text for a reader — an indented tree, a
// child two spaces under its parent — and as JSON (schema in docs/formats.md, "rayvec trace").
#pragma once
#include <string>

#include "render/ray_tree.h"

namespace rayvec {

std::string ray_tree_text(const PixelTrace& trace, const Scene& scene);
std::string ray_tree_json(const PixelTrace& trace, const Scene& scene);

}  // namespace rayvec
