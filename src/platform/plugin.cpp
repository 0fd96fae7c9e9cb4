#include "platform/plugin.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace rayvec {
namespace {

std::vector<std::string> candidate_paths(const char* env_var, const char* file_name, const char* build_dir) {
  if (const char* env = std::getenv(env_var); env && *env) return {env};  // the user's choice only
  std::vector<std::string> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / file_name).string());
  if (build_dir) paths.push_back(std::string(build_dir) + "/" + file_name);
  return paths;
}

}  // namespace

std::string plugin_problem(const Plugin& p, const char* file_name, const std::string& hint) {
  if (!p.error.empty()) return p.error;
  return std::string(file_name) + " not found (looked for " + p.tried + ")" + hint;
}

Plugin open_plugin(const char* env_var, const char* file_name, const char* build_dir, bool global) {
  Plugin p;
  for (const std::string& path : candidate_paths(env_var, file_name, build_dir)) {
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
