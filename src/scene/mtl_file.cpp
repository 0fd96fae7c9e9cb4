#include "scene/mtl_file.h"

#include <filesystem>

#include "io/text_file.h"
#include "scene/mtl_parser.h"
#include "scene/mtl_validate.h"
#include "scene/texture_path.h"

namespace rayvec {

std::vector<Material> read_mtl_file(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<MtlMaterial> parsed = parse_mtl(read_text_file(path), path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  std::vector<Material> out;
  out.reserve(parsed.size());
  for (MtlMaterial& m : parsed) {
    validate_mtl_material(m, path, warnings);
    Material& mat = m.material;
    if (!mat.map_Kd.empty()) {
      const std::string written = mat.map_Kd;
      mat.map_Kd = resolve_named_file(written, dir);
      const std::string problem = texture_file_problem(mat.map_Kd);
      if (!problem.empty()) {
        warnings.push_back(path + ":" + std::to_string(m.lines.map_Kd) + ": material '" + mat.name +
                           "': texture '" + written + "' (" + mat.map_Kd + ") " + problem +
                           "; drawn with Kd only");
        mat.map_Kd.clear();
      }
    }
    out.push_back(std::move(mat));
  }
  return out;
}

}  // namespace rayvec
