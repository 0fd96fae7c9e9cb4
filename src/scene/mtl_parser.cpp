#include "scene/mtl_parser.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "io/csv_fields.h"
#include "io/input_error.h"
#include "io/text_file.h"
#include "scene/material_names.h"

namespace rayvec {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string_view next_token(std::string_view& line) {
  line = trim(line);
  std::size_t j = 0;
  while (j < line.size() && !is_space(line[j])) ++j;
  const std::string_view token = line.substr(0, j);
  line.remove_prefix(j);
  return token;
}

// A finite float, or nothing.
bool parse_float(std::string_view token, float& out) {
  if (token.size() > 1 && token.front() == '+') token.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (token.empty() || end != token.data() + token.size()) return false;
  // from_chars leaves `value` at 0 when out of range: strtod tells 1e400 from 1e-400.
  if (ec == std::errc::result_out_of_range)
    value = std::strtod(std::string(token).c_str(), nullptr);
  else if (ec != std::errc())
    return false;
  if (!std::isfinite(value) || !std::isfinite(static_cast<float>(value))) return false;
  out = static_cast<float>(value);
  return true;
}

class LineReader {
 public:
  LineReader(const std::string& path, std::size_t line) : path_(path), line_(line) {}

  float number(std::string_view& rest, std::string_view key) const {
    const std::string_view token = next_token(rest);
    float value = 0;
    if (token.empty()) throw InputError(path_, line_, "`" + std::string(key) + "` needs a number");
    if (!parse_float(token, value))
      throw InputError(path_, line_,
                       "`" + std::string(key) + "` value '" + printable(token) +
                           "' is not a finite number (write a decimal such as 0.8)");
    return value;
  }
  Vec3f colour(std::string_view rest, std::string_view key) const {
    const float r = number(rest, key);
    if (trim(rest).empty()) return {r, r, r};
    const float g = number(rest, key);
    const float b = number(rest, key);
    return {r, g, b};
  }

 private:
  const std::string& path_;
  std::size_t line_;
};

// Texture options and how many values follow each (-o, -s, -t take one to three numbers).
int option_values(std::string_view option) {
  for (const char* one :
       {"-blendu", "-blendv", "-bm", "-boost", "-cc", "-clamp", "-imfchan", "-texres", "-type"})
    if (option == one) return 1;
  if (option == "-mm") return 2;
  if (option == "-o" || option == "-s" || option == "-t") return 3;
  return 0;
}

// A `map_Kd` line's rest: its options — `-s` and `-o` read into `mat` (their first two values,
// where they are numbers), the others skipped — and the texture name, the rest of the line with
// quotes removed.
void read_texture_reference(std::string_view rest, Material& mat) {
  for (;;) {
    rest = trim(rest);
    std::string_view probe = rest;
    const std::string_view option = next_token(probe);
    const int values = option_values(option);
    if (values == 0) break;
    rest = probe;
    std::array<float, 2>* target = option == "-s"   ? &mat.map_Kd_scale
                                   : option == "-o" ? &mat.map_Kd_offset
                                                    : nullptr;
    for (int k = 0; k < values; ++k) {
      std::string_view after = rest;
      const std::string_view value = next_token(after);
      float number = 0;
      const bool is_number = parse_float(value, number);
      // -o/-s/-t take up to three numbers; the others take exactly their count of words.
      if (value.empty() || (values == 3 && k > 0 && !is_number)) break;
      if (target && k < 2 && is_number) (*target)[k] = number;
      rest = after;
    }
  }
  rest = trim(rest);
  if (rest.size() >= 2 && (rest.front() == '"' || rest.front() == '\'') && rest.back() == rest.front())
    rest = rest.substr(1, rest.size() - 2);
  mat.map_Kd = std::string(rest);
}

MtlMaterial new_material(std::string name, std::size_t line) {
  MtlMaterial m;
  m.material.name = std::move(name);
  m.material.Kd = {0, 0, 0};
  m.material.Tf = {0, 0, 0};
  m.material.Ns = 1;
  m.material.illum = 0;
  m.lines.newmtl = line;
  return m;
}

}  // namespace

std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& path) {
  std::vector<MtlMaterial> out;
  bool has_tr = false;
  std::size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    std::string_view rest = next_text_line(text, pos);
    ++line_no;
    const std::string_view key = next_token(rest);
    if (key.empty() || key.front() == '#') continue;
    if (key == "newmtl") {
      // A nameless material (as tinyobjloader, kept but unreachable: `usemtl` needs a name).
      out.push_back(new_material(written_material_name(rest), line_no));
      has_tr = false;
      continue;
    }
    if (out.empty()) continue;
    MtlMaterial& m = out.back();
    Material& mat = m.material;
    const LineReader r(path, line_no);
    if (key == "Ka") {
      mat.Ka = r.colour(rest, key), m.lines.Ka = line_no;
    } else if (key == "Kd") {
      mat.Kd = r.colour(rest, key), m.lines.Kd = line_no;
    } else if (key == "Ks") {
      mat.Ks = r.colour(rest, key), m.lines.Ks = line_no;
    } else if (key == "Ke") {
      mat.Ke = r.colour(rest, key), m.lines.Ke = line_no;
    } else if (key == "Tf" || key == "Kt") {
      mat.Tf = r.colour(rest, key), m.lines.Tf = line_no;
    } else if (key == "Ns") {
      mat.Ns = r.number(rest, key), m.lines.Ns = line_no;
    } else if (key == "Ni") {
      mat.Ni = r.number(rest, key), m.lines.Ni = line_no;
    } else if (key == "d") {
      mat.d = r.number(rest, key), m.lines.d = line_no, has_tr = false;
    } else if (key == "Tr") {
      const float tr = r.number(rest, key);
      // `d` is the MTL specification's key and wins over `Tr` wherever each stands.
      if (m.lines.d == 0 || has_tr) mat.d = 1.0f - tr, m.lines.d = line_no, has_tr = true;
    } else if (key == "illum") {
      const std::string_view token = next_token(rest);
      int value = 0;
      const auto [end_ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
      m.lines.illum = line_no;
      if (token.empty() || ec != std::errc() || end_ptr != token.data() + token.size())
        m.illum_text = token.empty() ? std::string("(nothing)") : printable(token);
      else
        mat.illum = value, m.illum_text.clear();
    } else if (key == "map_Kd") {
      mat.map_Kd_scale = {1, 1};  // a later map_Kd replaces the earlier one, options included
      mat.map_Kd_offset = {0, 0};
      read_texture_reference(rest, mat);
      m.lines.map_Kd = line_no;
      if (m.lines.Kd == 0) mat.Kd = {0.6f, 0.6f, 0.6f};
    }
  }
  return out;
}

}  // namespace rayvec
