// open_plugin: finds and dlopens one of rayvec's modules — shared libraries that keep a heavy
// dependency (OpenImageIO, MPI) off the start-up path of every command — the same way for each:
// the path in an environment variable alone when it is set, else beside the running executable,
// then in the build tree the binary came from.
#pragma once
#include <string>

namespace rayvec {

struct Plugin {
  void* handle = nullptr;  // null: not found (error empty) or found but not loadable (error says why)
  std::string path;        // the file opened
  std::string error;
  std::string tried;  // every path looked at, for a "not found" message
};

// `global`: RTLD_GLOBAL, for modules whose own plugins resolve symbols through the global scope.
Plugin open_plugin(const char* env_var, const char* file_name, bool global);

// Why `p`, opened by open_plugin(…, file_name, …), did not load: dlopen's error, or
// "FILE not found (looked for …)" followed by `hint` (how to get or point to the module).
std::string plugin_problem(const Plugin& p, const char* file_name, const std::string& hint);
// The same with the usual hint: the module is built beside the binary, or `env_var` names it.
std::string plugin_problem(const Plugin& p, const char* file_name, const char* env_var);

// dlsym: the symbol's address, or null.
void* plugin_symbol(const Plugin& plugin, const char* name);

}  // namespace rayvec
