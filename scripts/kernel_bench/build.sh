#!/bin/sh
# Builds the brute-force kernel experiment harness of docs/benchmarks.md ("Brute-force kernel")
# against an existing Release build of librayvec.a. Not part of the product build.
#   scripts/kernel_bench/build.sh BUILD_DIR
#   RV_VARIANT=1 OUT/kernel_bench_foundation 50000 64 mt 0   # the foundation kernel (commit 7311440)
#   OUT/kernel_bench_early 10000 100 mt 0 ; RV_VARIANT=1 OUT/kernel_bench_early 10000 100 mt 0
#   RV_AB=1 OUT/kernel_bench_sign 50000 200 mt 64            # product vs variant, paired in one process
#   RV_AB=1 OUT/kernel_bench_prev 50000 100 mt 64            # today's kernel vs the one before row 11
# Arguments: triangles, image side of the ray subset, intersector, rays per closest_batch call
# (0 = one closest call per ray). Prints G tests/s on the thread's CPU time and tests/cycle against
# a dependent-add loop timed the same way (see kernel_bench.cpp for RV_AB / RV_REPS).
# The pinned kernels (foundation, prev) index the triangle rows as plain arrays, the layout before
# 16a0c3d (blocked rows): build them against a librayvec.a of bba758d or earlier. The early and
# sign variants read rows through slot_offset and work with the current library.
set -e
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../../src" && pwd)
build=${1:?usage: build.sh BUILD_DIR}
out=${OUT:-$build/kernel_bench}
mkdir -p "$out"
isa="-mavx2 -mfma -mavx512f -mavx512dq -mavx512bw -mavx512vl -ffp-contract=off"
git -C "$here" show 7311440:src/kernels/moller_trumbore.inl > "$out/foundation_mt.inl"
# variants written against the kernel as of 96ea2dd (before the packet refactor), pinned
git -C "$here" show 96ea2dd:src/kernels/moller_trumbore.inl > "$out/pinned_mt.inl"
git -C "$here" show c06ea87:src/kernels/moller_trumbore.inl > "$out/prev_mt.inl"  # before row 11
g++ -std=c++20 -O3 $isa -I"$src" -I"$out" -c "$here/foundation_variant.cpp" -o "$out/foundation.o"
g++ -std=c++20 -O3 $isa -I"$src" -I"$out" -c "$here/early_outs_variant.cpp" -o "$out/early.o"
g++ -std=c++20 -O3 $isa -I"$src" -I"$out" -c "$here/sign_test_variant.cpp" -o "$out/sign.o"
g++ -std=c++20 -O3 $isa -I"$src" -I"$out" -c "$here/prev_variant.cpp" -o "$out/prev.o"
for v in foundation early sign prev; do
  g++ -std=c++20 -O2 -I"$src" "$here/kernel_bench.cpp" "$out/$v.o" "$build/librayvec.a" -fopenmp \
      -o "$out/kernel_bench_$v"
done
echo "built $out/kernel_bench_foundation, _early, _sign and _prev"
