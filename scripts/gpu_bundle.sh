#!/usr/bin/env bash
# Builds, on this machine, what scripts/gpu_check.sh --prebuilt runs on a GPU machine that has nvcc
# but none of rayvec's Debian packages (the device machines: a CUDA image, no package registry):
# build-gpu/ with the CUDA backend (every architecture of RAYVEC_CUDA_ARCHITECTURES), then
# build-gpu/bundle/ with the binary, the Cuda test binary and the shared libraries they need beyond
# the C and C++ runtimes, and where this tree lives (the tests name their data by absolute path).
#   scripts/gpu_bundle.sh            # then carry build-gpu/bundle and run, in the copied tree:
#   bash scripts/gpu_check.sh --prebuilt build-gpu/bundle RESULTS_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-gpu"
bundle="$build/bundle"
nvcc="$(command -v nvcc || true)"
[[ -z "$nvcc" && -x /usr/local/cuda/bin/nvcc ]] && nvcc=/usr/local/cuda/bin/nvcc
if [[ -z "$nvcc" ]]; then
  echo "gpu_bundle: nvcc not found (install the CUDA toolkit or put nvcc on PATH)" >&2
  exit 1
fi
"$root/scripts/install-deps.sh"
# Embree off: a benchmark rival only, and its TBB would travel too
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_CUDA=ON -DRAYVEC_MPI=OFF \
  -DRAYVEC_WITH_EMBREE=OFF -DCMAKE_CUDA_COMPILER="$nvcc" >/dev/null
cmake --build "$build" -j "$(nproc)" --target rayvec-cli rayvec_cuda_tests

rm -rf "$bundle"
mkdir -p "$bundle/lib"
cp "$build/rayvec" "$build/tests/rayvec_cuda_tests" "$bundle/"
# every library the two binaries load, except the C runtime, libm, libgcc_s and libstdc++ (there in any
# CUDA image, and newer than Debian 12's)
for binary in "$bundle/rayvec" "$bundle/rayvec_cuda_tests"; do
  ldd "$binary" | awk '$3 ~ /^\// {print $3}' |
    grep -vE '/(libc|libm|libgcc_s|libstdc\+\+|ld-linux-x86-64|libpthread|libdl|librt)\.so' |
    while read -r lib; do cp -L "$lib" "$bundle/lib/"; done
done
echo "$root" >"$bundle/source_dir"
echo "$build" >"$bundle/build_dir"
git -C "$root" rev-parse --short HEAD >"$bundle/commit" 2>/dev/null || echo unknown >"$bundle/commit"
echo "gpu_bundle: $(du -sh "$bundle" | cut -f1) in $bundle ($(ls "$bundle/lib" | wc -l) libraries)"
echo "on the GPU machine, in the copied tree: bash scripts/gpu_check.sh --prebuilt build-gpu/bundle RESULTS_DIR"
