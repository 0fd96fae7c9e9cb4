#include "platform/plugin.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace rayvec {
namespace {

// Where the build put every module (beside the binary it built): RAYVEC_MODULE_DIR, set on this file
// by the build.
#ifdef RAYVEC_MODULE_DIR
constexpr const char* kBuildDir = RAYVEC_MODULE_DIR;
#else
constexpr const char* kBuildDir = nullptr;
#endif

std::vector<std::string> candidate_paths(const char* env_var, const char* file_name) {
  if (const char* env = std::getenv(env_var); env && *env) return {env};  // the user's choice only
  std::vector<std::string> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / file_name).string());
  if (kBuildDir) paths.push_back(std::string(kBuildDir) + "/" + file_name);
  return paths;
}

}  // namespace

std::string plugin_problem(const Plugin& p, const char* file_name, const std::string& hint) {
  if (!p.error.empty()) return p.error;
  return std::string(file_name) + " not found (looked for " + p.tried + ")" + hint;
}

std::string plugin_problem(const Plugin& p, const char* file_name, const char* env_var) {
  return plugin_problem(
      p, file_name,
      std::string("; it is built beside the rayvec binary, or set ") + env_var + " to its path");
}

Plugin open_plugin(const char* env_var, const char* file_name, bool global) {
  Plugin p;
  for (const std::string& path : candidate_paths(env_var, file_name)) {
    p.tried += (p.tried.empty() ? "" : ", ") + path;
    if (::access(path.c_str(), F_OK) != 0) continue;
    p.path = path;
    p.handle = ::dlopen(path.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
    if (!p.handle) p.error = "cannot load " + path + ": " + ::dlerror();
    return p;
  }
  return p;
}

void* plugin_symbol(const Plugin& plugin, const char* name) {
  return plugin.handle ? ::dlsym(plugin.handle, name) : nullptr;
}

}  // namespace rayvec
