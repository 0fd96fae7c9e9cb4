#include "distributed/mpi_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace rayvec {
namespace {

std::vector<std::string> candidate_paths() {
  if (const char* env = std::getenv("RAYVEC_MPI_MODULE"); env && *env) return {env};
  std::vector<std::string> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / kMpiModuleName).string());
#ifdef RAYVEC_MPI_MODULE_DIR
  paths.push_back(std::string(RAYVEC_MPI_MODULE_DIR) + "/" + kMpiModuleName);
#endif
  return paths;
}

template <class Fn>
void bind(void* handle, const char* name, Fn& fn) {
  fn = reinterpret_cast<Fn>(::dlsym(handle, name));
}

}  // namespace

MpiModule load_mpi_module() {
  MpiModule m;
  std::string tried;
  for (const std::string& path : candidate_paths()) {
    tried += (tried.empty() ? "" : ", ") + path;
    if (::access(path.c_str(), F_OK) != 0) continue;
    // RTLD_GLOBAL: OpenMPI's own plugins, loaded by MPI_Init, resolve symbols of libmpi through the
    // global scope.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
      m.error = "cannot load " + path + ": " + ::dlerror();
      return m;
    }
    RayvecMpiAbiFn abi = nullptr;
    bind(handle, "rayvec_mpi_abi", abi);
    bind(handle, "rayvec_mpi_init", m.init);
    bind(handle, "rayvec_mpi_finalize", m.finalize);
    bind(handle, "rayvec_mpi_abort", m.abort);
    bind(handle, "rayvec_mpi_allreduce", m.allreduce);
    bind(handle, "rayvec_mpi_bcast", m.bcast);
    bind(handle, "rayvec_mpi_send", m.send);
    bind(handle, "rayvec_mpi_recv", m.recv);
    bind(handle, "rayvec_mpi_probe", m.probe);
    if (!abi || abi() != kRayvecMpiAbi || !m.init || !m.finalize || !m.abort || !m.allreduce || !m.bcast ||
        !m.send || !m.recv || !m.probe) {
      m = MpiModule{};
      m.error = path + " is not a rayvec " + RAYVEC_VERSION + " MPI module (rebuild rayvec)";
    }
    return m;
  }
  m.error = std::string(kMpiModuleName) + " not found (looked for " + tried +
            "): this rayvec was built without MPI; configure with -DRAYVEC_MPI=ON "
            "(docs/distributed.md), or run it without a launcher";
  return m;
}

}  // namespace rayvec
