#include "scene/tinyobj_text.h"

#include <algorithm>

#include "io/text_file.h"

namespace rayvec {

std::string text_for_tinyobjloader(std::string_view text, std::vector<UsemtlLine>& usemtl_lines,
                                   const MtlFileExists& exists) {
  std::string out;
  out.reserve(text.size());
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t start = pos;
    const std::string_view line = next_text_line(text, pos);
    ++line_no;
    const std::size_t indent = std::min(line.find_first_not_of(" \t"), line.size());
    const std::string_view end = text.substr(start + line.size(), pos - start - line.size());
    if (line.compare(indent, 6, "mtllib") == 0 && line.size() > indent + 6 &&
        (line[indent + 6] == ' ' || line[indent + 6] == '\t')) {
      // tinyobjloader's test for the keyword, and the rest after its one blank
      out.append(line.substr(0, indent + 7)).append(mtllib_text(line.substr(indent + 7), exists)).append(end);
      continue;
    }
    if (line.size() > indent + 1 && (line[indent] == 'l' || line[indent] == 'p') &&
        (line[indent + 1] == ' ' || line[indent + 1] == '\t')) {
      out.append(end);  // tinyobjloader's test for a line or point, which rayvec does not draw
      continue;
    }
    if (line.compare(indent, 6, "usemtl") != 0) {
      out.append(text.substr(start, pos - start));
      continue;
    }
    // tinyobjloader matches the keyword as a prefix (`usemtlname` too) and skips the blanks after it
    const std::string key = material_key(written_material_name(line.substr(indent + 6)));
    out.append(line.substr(0, indent + 6)).append(" ").append(key);
    out.append(end);
    usemtl_lines.push_back({line_no, key});
  }
  return out;
}

}  // namespace rayvec
