// Material names as `usemtl` lines give them, their keys for tinyobjloader, `mtllib` names, and
// the warning for a missing material.
#include "scene/material_names.h"

#include <algorithm>

namespace rayvec {
namespace {

constexpr char kKeyBlank = '\x1f';
constexpr std::string_view kUnknownHead = "material [ '", kUnknownTail = "' ] not found in .mtl";
constexpr std::string_view kLineHead = " (line ";

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

std::string written_material_name(std::string_view after_keyword) {
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

std::string mtllib_text(std::string_view rest, const MtlFileExists& exists) {
  std::string out(rest);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i] == '\\' && (i + 1 == out.size() || out[i + 1] != ' ')) out[i] = '/';
  const std::size_t first = out.find_first_not_of(' '), last = out.find_last_not_of(' ');
  if (first == std::string::npos || out.find('\\') != std::string::npos) return out;
  const std::string whole = out.substr(first, last - first + 1);
  if (whole.find(' ') == std::string::npos || !exists(whole)) return out;
  std::string escaped;
  for (const char c : whole) escaped.append(c == ' ' ? "\\ " : std::string(1, c));
  return escaped;
}

std::string unknown_material_text(const std::string& key, std::size_t line) {
  return std::string(kUnknownHead) + key + std::string(kUnknownTail) + std::string(kLineHead) +
         std::to_string(line) + ")";
}

bool parse_unknown_material(std::string_view warning, std::string& key, std::size_t& line) {
  if (warning.substr(0, kUnknownHead.size()) != kUnknownHead) return false;
  const std::size_t tail = warning.rfind(kUnknownTail);
  if (tail == std::string_view::npos || tail < kUnknownHead.size()) return false;
  const std::string_view rest = warning.substr(tail + kUnknownTail.size());
  line = 0;
  if (!rest.empty()) {
    if (rest.substr(0, kLineHead.size()) != kLineHead || rest.size() < kLineHead.size() + 2 ||
        rest.back() != ')')
      return false;
    for (const char c : rest.substr(kLineHead.size(), rest.size() - kLineHead.size() - 1)) {
      if (c < '0' || c > '9') return false;
      line = line * 10 + std::size_t(c - '0');
    }
  }
  key = std::string(warning.substr(kUnknownHead.size(), tail - kUnknownHead.size()));
  return true;
}

}  // namespace rayvec
