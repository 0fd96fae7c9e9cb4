#!/usr/bin/env bash
# Builds the `rayvec` binary of another commit and prints its path: the old side of an A/B, e.g. a
# Decision of docs/benchmarks.md re-measured on a CPU it was not decided on
# (docs/benchmarks.md#re-measuring-a-decision):
#
#   scripts/bench_rays_rounds.py 6 sphere1m.obj "--isa avx2" old=$(scripts/build_at.sh 4e1cb89) new=build/rayvec
#
# Usage: scripts/build_at.sh COMMIT [CACHE_DIR]
# The commit's tree is exported (git archive: no worktree, the checkout untouched) to
# CACHE_DIR/<commit> (default ${TMPDIR:-/tmp}/rayvec-at) and built there as scripts/build.sh builds
# (Release, no CUDA, no MPI; Embree's module when libembree-dev is installed), only the binary and
# the modules it loads. A binary already there is reused. Progress goes to stderr, the path to stdout.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: scripts/build_at.sh COMMIT [CACHE_DIR]" >&2
  exit 2
fi
if ! commit="$(git -C "$root" rev-parse --verify --quiet "$1^{commit}")"; then
  echo "build_at: '$1' is not a commit of $root (git fetch it, or give a full hash)" >&2
  exit 2
fi
cache="${2:-${TMPDIR:-/tmp}/rayvec-at}"
dir="$cache/${commit:0:12}"
binary="$dir/build/rayvec"
if [ ! -x "$binary" ]; then
  if [ ! -f "$dir/src/CMakeLists.txt" ]; then
    rm -rf "$dir/src"
    mkdir -p "$dir/src.partial"
    git -C "$root" archive "$commit" | tar -x -C "$dir/src.partial"
    mv "$dir/src.partial" "$dir/src"
  fi
  echo "build_at: building ${commit:0:12} in $dir/build" >&2
  cmake -S "$dir/src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release -DRAYVEC_CUDA=OFF -DRAYVEC_MPI=OFF >&2
  cmake --build "$dir/build" -j "$(nproc)" --target rayvec-cli >&2
fi
echo "$binary"
