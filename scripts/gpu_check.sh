#!/usr/bin/env bash
# The one script to run on a machine with an NVIDIA GPU (docs/gpu.md, "Verified where"): builds the
# CUDA configuration, runs the Cuda tests (now with a device: the kernels against the host math and
# the CPU, bit for bit), `rayvec info` and `rayvec bench visibility`, and writes every log and result
# under RESULTS_DIR. Each step has its own time limit, so the whole run stays under 5 minutes on a
# 16-core machine and always leaves its logs; the exit status is 1 if any step failed.
#   scripts/gpu_check.sh RESULTS_DIR                      # builds here: needs rayvec's Debian packages
#   scripts/gpu_check.sh --prebuilt BUNDLE RESULTS_DIR     # runs what scripts/gpu_bundle.sh built elsewhere
# Environment: RAYVEC_CUDA_BUILD (default build-cuda), RAYVEC_CUDA_ARCHITECTURES (default native:
# only the GPU present, to build in time; the full list is what scripts/test_cuda.sh compiles).
set -euo pipefail
bundle=""
if [[ $# -eq 3 && "$1" == "--prebuilt" ]]; then
  bundle="$(cd "$2" && pwd)"
  shift 2
fi
if [[ $# -ne 1 ]]; then
  echo "usage: $0 [--prebuilt BUNDLE] RESULTS_DIR" >&2
  exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mkdir -p "$1"
results="$(cd "$1" && pwd)"
build="${RAYVEC_CUDA_BUILD:-$root/build-cuda}"
nvcc="$(command -v nvcc || true)"
[[ -z "$nvcc" && -x /usr/local/cuda/bin/nvcc ]] && nvcc=/usr/local/cuda/bin/nvcc
failed=()
start=$(date +%s)

# step NAME LIMIT_SECONDS COMMAND...: runs with a time limit, output to RESULTS/NAME.log
step() {
  local name="$1" limit="$2"
  shift 2
  local t0=$(date +%s) status=0
  timeout "$limit" "$@" >"$results/$name.log" 2>&1 || status=$?
  echo "$name: exit $status, $(($(date +%s) - t0)) s" | tee -a "$results/summary.txt"
  [[ $status -eq 0 ]] || failed+=("$name")
}

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //') ($(nproc) cores)"
  echo "nvcc: ${nvcc:-none}"
} >"$results/summary.txt"
(nvidia-smi || echo "nvidia-smi: not available") >"$results/nvidia-smi.txt" 2>&1

if [[ -n "$bundle" ]]; then
  # The binaries name the tree they were built in (the tests' data, the CLI): make that path this tree.
  source_dir="$(cat "$bundle/source_dir")"
  build_dir="$(cat "$bundle/build_dir")"
  if [[ "$source_dir" != "$root" && ! -e "$source_dir" ]]; then
    mkdir -p "$(dirname "$source_dir")"
    ln -s "$root" "$source_dir"
  fi
  mkdir -p "$build_dir/tests"
  cp "$bundle/rayvec" "$build_dir/rayvec"
  cp "$bundle/rayvec_cuda_tests" "$build_dir/tests/rayvec_cuda_tests"
  export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  echo "prebuilt: commit $(cat "$bundle/commit"), built in $source_dir" >>"$results/summary.txt"
  step info 15 "$build_dir/rayvec" info
  step tests 90 "$build_dir/tests/rayvec_cuda_tests" --gtest_filter='Cuda*'
  step bench_visibility 120 "$build_dir/rayvec" bench visibility --rings 100,200,400 --tiles 64,256,1024 \
    --cpu-budget 1e9
  cp "$results/bench_visibility.log" "$results/bench_visibility.md"
  echo "total: $(($(date +%s) - start)) s; failed: ${failed[*]:-none}" | tee -a "$results/summary.txt"
  [[ ${#failed[@]} -eq 0 ]]
  exit
fi

if [[ -z "$nvcc" ]]; then
  echo "nvcc not found: nothing to build" | tee -a "$results/summary.txt"
  exit 1
fi

configure=(cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_CUDA=ON -DCMAKE_CUDA_COMPILER="$nvcc")
configure+=("-DRAYVEC_CUDA_ARCHITECTURES=${RAYVEC_CUDA_ARCHITECTURES:-native}")
# limits: 30 + 110 + 15 + 60 + 80 s = under 5 minutes
step configure 30 "${configure[@]}"
step build 110 cmake --build "$build" -j "$(nproc)" --target rayvec-cli rayvec_cuda_tests
step info 15 "$build/rayvec" info
cp "$results/info.log" "$results/info.txt"
step ctest 60 bash -c "cd '$build' && ctest --output-on-failure -j 4 -R Cuda"
# the study's size (rings 100), 4x and 16x; CPU rows only where they fit the budget
step bench_visibility 80 "$build/rayvec" bench visibility --rings 100,200,400 --tiles 64,256,1024 \
  --cpu-budget 1e9
cp "$results/bench_visibility.log" "$results/bench_visibility.md"

echo "total: $(($(date +%s) - start)) s; failed: ${failed[*]:-none}" | tee -a "$results/summary.txt"
[[ ${#failed[@]} -eq 0 ]]
