#include "scene/texture_path.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "io/text_file.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

bool path_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

fs::path absolute_normal(const fs::path& p) {
  std::error_code ec;
  const fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

bool same_ignoring_ascii_case(const std::string& a, const std::string& b) {
  const auto lower = [](unsigned char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : char(c); };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

// `rel` under `base`, each component that does not exist as written matched by the entry of its
// directory whose name differs only in ASCII case (the first in name order, so the choice does
// not depend on the directory's order): textures named on a case-insensitive file system
// (`Textures\Wood.JPG` for textures/wood.jpg). Empty when some component has no such entry.
fs::path find_ignoring_case(const fs::path& base, const fs::path& rel) {
  fs::path at = base;
  for (const fs::path& part : rel) {
    if (part.empty() || part == ".") continue;
    if (part == ".." || path_exists(at / part)) {
      at /= part;
      continue;
    }
    std::error_code ec;
    std::string best;
    for (fs::directory_iterator it(at, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (same_ignoring_ascii_case(name, part.string()) && (best.empty() || name < best)) best = name;
    }
    if (best.empty()) return {};
    at /= best;
  }
  return at;
}

}  // namespace

std::string resolve_named_file(const std::string& name, const std::string& dir_name) {
  const fs::path dir(dir_name);
  auto beside = [&](const fs::path& p) { return absolute_normal(p.is_absolute() ? p : dir / p); };
  const fs::path literal = beside(name);
  if (path_exists(literal)) return literal.string();
  std::string slashed = name;
  std::replace(slashed.begin(), slashed.end(), '\\', '/');
  // `C:/models/a.jpg`: a drive letter means nothing here.
  const bool drive = slashed.size() >= 2 && slashed[1] == ':';
  const fs::path guess = drive ? fs::path(slashed.substr(2)) : fs::path(slashed);
  const fs::path resolved = beside(guess);
  if (path_exists(resolved)) return resolved.string();
  const fs::path file_name = guess.filename();
  if (!file_name.empty() && path_exists(dir / file_name)) return absolute_normal(dir / file_name).string();
  for (const auto& [base, rel] :
       {std::pair<fs::path, fs::path>{guess.is_absolute() ? fs::path() : dir, guess}, {dir, file_name}}) {
    if (base.empty() || rel.empty()) continue;
    const fs::path found = find_ignoring_case(base, rel.relative_path());
    if (!found.empty()) return absolute_normal(found).string();
  }
  return resolved.string();
}

std::string texture_file_problem(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && !fs::exists(status)) {
    if (ec == std::errc::no_such_file_or_directory || ec == std::errc::not_a_directory) return "not found";
    return "cannot be looked up: " + ec.message();
  }
  if (!fs::is_regular_file(status)) return "is not a regular file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot be opened for reading";
  const auto size = fs::file_size(path, ec);
  if (!ec && size > max_input_bytes())
    return "is larger than the " + std::to_string(max_input_bytes() / 1000000) +
           " MB input limit (RAYVEC_MAX_INPUT_MB)";
  return "";
}

}  // namespace rayvec
