// json_string: a string as a JSON string literal, for the commands that print JSON by hand
// (nlohmann-json belongs to the scene loader alone). Escapes quote and backslash; drops control
// characters, which never occur in the names and paths these commands print.
#pragma once
#include <string>

namespace rayvec {

inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

}  // namespace rayvec
