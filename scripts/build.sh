#!/usr/bin/env bash
# Configures and builds rayvec (Release) into build/. Used by run.sh and test.sh. Without CUDA and MPI,
# whatever the machine has installed, so the default stage's tests stay the same (scripts/test_cuda.sh and
# scripts/test_mpi.sh build those configurations); extra arguments go to cmake after these.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_CUDA=OFF -DRAYVEC_MPI=OFF "$@" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
