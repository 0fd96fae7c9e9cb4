#!/usr/bin/env bash
# CI stage of the CUDA configuration (docs/gpu.md): configures build-cuda/ with RAYVEC_CUDA=ON, builds
# only what the Cuda tests need (the CLI and rayvec_cuda_tests), runs `ctest -R Cuda` (the device
# math against the CPU kernels on the host; the GPU tests skip without a device) and checks that
# --device cuda fails cleanly when there is no GPU. Without nvcc it says so and exits 0.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYVEC_CUDA_BUILD:-$root/build-cuda}"
nvcc="$(command -v nvcc || true)"
[[ -z "$nvcc" && -x /usr/local/cuda/bin/nvcc ]] && nvcc=/usr/local/cuda/bin/nvcc
if [[ -z "$nvcc" ]]; then
  echo "skipped: nvcc not found (install the CUDA toolkit or put nvcc on PATH)"
  exit 0
fi
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_CUDA=ON -DRAYVEC_MPI=OFF \
  -DCMAKE_CUDA_COMPILER="$nvcc" >/dev/null
cmake --build "$build" -j "$(nproc)" --target rayvec-cli rayvec_cuda_tests
(cd "$build" && ctest --output-on-failure -j "$(nproc)" -R Cuda)

# smoke: --device cuda on the hand-checked files; without a GPU exit 1 naming it and no output
data="$root/tests/data/visibility"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
status=0
"$build/rayvec" visibility --verts "$data/verts.csv" --faces "$data/meshes.csv" --device cuda \
  -o "$out/vis.txt" 2>"$out/err" || status=$?
if "$build/rayvec" info | grep -q '^cuda device 0:'; then
  [[ $status -eq 0 ]] && cmp "$out/vis.txt" "$data/expected.txt" || { echo "FAIL: --device cuda on a GPU"; exit 1; }
  echo "smoke: --device cuda matches expected.txt on $("$build/rayvec" info | sed -n 's/^cuda device 0: //p')"
else
  if [[ $status -ne 1 ]] || ! grep -q 'no CUDA device found' "$out/err" || [[ -e "$out/vis.txt" ]]; then
    echo "FAIL: without a GPU --device cuda must exit 1 saying 'no CUDA device found' and write nothing"
    cat "$out/err"
    exit 1
  fi
  echo "smoke: no GPU here: --device cuda exits 1 ($(cat "$out/err")), nothing written"
fi
