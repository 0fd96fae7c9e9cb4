#!/usr/bin/env bash
# The MPI stage of CI: installs OpenMPI (scripts/install-deps.sh --with-mpi), configures build-mpi/
# with -DRAYVEC_MPI=ON (Release), builds only what the Mpi* tests run (the rayvec binary,
# librayvec_mpi.so and rayvec_mpi_tests) and runs them: each starts rayvec under
# `mpirun -np 2 --oversubscribe` (docs/distributed.md). As root, OpenMPI needs the two
# OMPI_ALLOW_RUN_AS_ROOT variables, which the tests set themselves.
# Usage: scripts/test_mpi.sh [CTEST ARGUMENTS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYVEC_MPI_BUILD:-$root/build-mpi}"
"$root/scripts/install-deps.sh" --with-mpi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_MPI=ON -DRAYVEC_CUDA=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target rayvec-cli rayvec_mpi rayvec_mpi_tests
cd "$build"
ctest --output-on-failure -R Mpi "$@"
