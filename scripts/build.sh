#!/usr/bin/env bash
# Configures and builds rayvec (Release) into build/. Used by run.sh and test.sh. Without MPI, whatever
# the machine has installed, so the default stage's tests stay the same (scripts/test_mpi.sh builds
# the MPI configuration); extra arguments such as -DRAYVEC_MPI=ON go to cmake after it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_MPI=OFF "$@" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
