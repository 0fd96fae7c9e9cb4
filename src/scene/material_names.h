// How an OBJ `usemtl` line names its material, the same on both OBJ readers: the whole rest of the
// line, so `usemtl Material #25` and `usemtl Material #26` are two materials. tinyobjloader reads
// only the first word (both were "Material", the first such material); its reading is kept apart
// from names with blanks by keys without them. And how `mtllib` names its files (Windows paths,
// names with spaces).
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rayvec {

// The material a `newmtl` or `usemtl` line names, given the text after the keyword (`usemtl
// name`, or `usemtlname` as tinyobjloader also reads it): leading and trailing blanks (space, tab,
// CR) removed, inner ones kept. One rule for both, so a name matches itself.
std::string written_material_name(std::string_view after_keyword);

// A material name as a key that tinyobjloader's `usemtl` reads whole (its first word): every
// space and tab written as the unit separator 0x1F; material_name undoes it. The key of a name
// without blanks is the name.
std::string material_key(std::string_view name);
std::string material_name(std::string_view key);

// A `usemtl` line: its number (1-based) and the material_key of its name.
struct UsemtlLine {
  std::size_t line;
  std::string key;
};

// Whether the name an `mtllib` line gives (separators already `/`) is an existing MTL file.
using MtlFileExists = std::function<bool(const std::string& name)>;

// The text after `mtllib ` as both OBJ readers hand it to tinyobjloader's reading, which splits it
// at spaces into names and reads `\` as an escape of the next character: every `\` that does not
// escape a space written as `/` (a path written on Windows, `mtllib ..\mats\a.mtl`, would read
// `..matsa.mtl`; `a\ b.mtl` stays one name with a space); then, where the whole text (without its
// outer blanks and without escapes) names an existing file, its spaces escaped, so that it is one
// name — `mtllib Low Poly Tree.mtl`, as some exporters write a name with spaces.
std::string mtllib_text(std::string_view rest, const MtlFileExists& exists);

// The warning for a `usemtl` line whose material no MTL file loaded before it defines, as both OBJ
// readers write it before load_obj words it for the user: tinyobjloader's words,
// "material [ 'KEY' ] not found in .mtl", then " (line N)". parse_unknown_material reads `key`
// and `line` back (line 0 when the text has none, as tinyobjloader writes it); false when
// `warning` is another warning.
std::string unknown_material_text(const std::string& key, std::size_t line);
bool parse_unknown_material(std::string_view warning, std::string& key, std::size_t& line);

}  // namespace rayvec
