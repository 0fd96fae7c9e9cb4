#include "scene/material_names.h"

#include <algorithm>

#include "io/text_file.h"

namespace rayvec {
namespace {

constexpr char kKeyBlank = '\x1f';

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

std::string usemtl_name(std::string_view after_keyword) {
  while (!after_keyword.empty() && is_blank(after_keyword.front())) after_keyword.remove_prefix(1);
  while (!after_keyword.empty() && is_blank(after_keyword.back())) after_keyword.remove_suffix(1);
  return std::string(after_keyword);
}

std::string material_key(std::string_view name) {
  std::string key(name);
  std::replace_if(
      key.begin(), key.end(), [](char c) { return c == ' ' || c == '\t'; }, kKeyBlank);
  return key;
}

std::string material_name(std::string_view key) {
  std::string name(key);
  std::replace(name.begin(), name.end(), kKeyBlank, ' ');
  return name;
}

std::string with_material_keys(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t start = pos;
    const std::string_view line = next_text_line(text, pos);
    const std::size_t indent = std::min(line.find_first_not_of(" \t"), line.size());
    if (line.compare(indent, 6, "usemtl") != 0) {
      out.append(text.substr(start, pos - start));
      continue;
    }
    // tinyobjloader matches the keyword as a prefix (`usemtlname` too) and skips the blanks after it
    out.append(line.substr(0, indent + 6))
        .append(" ")
        .append(material_key(usemtl_name(line.substr(indent + 6))));
    out.append(text.substr(start + line.size(), pos - start - line.size()));  // the line's end
  }
  return out;
}

}  // namespace rayvec
