#include "distributed/mpi_loader.h"

#include <string>

#include "platform/plugin.h"

namespace rayvec {
namespace {

template <class Fn>
void bind(const Plugin& plugin, const char* name, Fn& fn) {
  fn = reinterpret_cast<Fn>(plugin_symbol(plugin, name));
}

}  // namespace

MpiModule load_mpi_module() {
  MpiModule m;
  // RTLD_GLOBAL: OpenMPI's own plugins, loaded by MPI_Init, resolve symbols of libmpi through the
  // global scope.
  const Plugin p = open_plugin("RAYVEC_MPI_MODULE", kMpiModuleName, /*global=*/true);
  if (!p.handle) {
    m.error = plugin_problem(p, kMpiModuleName,
                             ": this rayvec was built without MPI; configure with -DRAYVEC_MPI=ON "
                             "(docs/distributed.md), or run it without a launcher");
    return m;
  }
  RayvecMpiAbiFn abi = nullptr;
  bind(p, "rayvec_mpi_abi", abi);
  bind(p, "rayvec_mpi_init", m.init);
  bind(p, "rayvec_mpi_finalize", m.finalize);
  bind(p, "rayvec_mpi_abort", m.abort);
  bind(p, "rayvec_mpi_allreduce", m.allreduce);
  bind(p, "rayvec_mpi_bcast", m.bcast);
  bind(p, "rayvec_mpi_send", m.send);
  bind(p, "rayvec_mpi_recv", m.recv);
  bind(p, "rayvec_mpi_probe", m.probe);
  if (!abi || abi() != kRayvecMpiAbi || !m.init || !m.finalize || !m.abort || !m.allreduce || !m.bcast ||
      !m.send || !m.recv || !m.probe) {
    m = MpiModule{};
    m.error = p.path + " is not a rayvec " + RAYVEC_VERSION + " MPI module (rebuild rayvec)";
  }
  return m;
}

}  // namespace rayvec
