#!/bin/sh
# Builds the BVH experiment harness of docs/benchmarks.md ("BVH quality and parallel build") against
# an existing Release build of librayvec.a. Not part of the product build.
#   scripts/bvh_bench/build.sh BUILD_DIR [VARIANT_TRAVERSAL.inl]
#   BUILD_DIR/bvh_bench/bvh_bench /tmp/sphere1m.obj 5 base: leaf16:max_leaf=16 variant:trv=1
set -e
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../../src" && pwd)
build=${1:?usage: build.sh BUILD_DIR [VARIANT.inl]}
out=${OUT:-$build/bvh_bench}
mkdir -p "$out"
inl=${2:-$src/bvh/bvh_traversal.inl}
isa="-mavx2 -mfma -mavx512f -mavx512dq -mavx512bw -mavx512vl -ffp-contract=off"
g++ -std=c++20 -O3 $isa -I"$src" -DRV_VARIANT_INL="\"$inl\"" $RV_CXXFLAGS -c "$here/variant_avx512.cpp" -o "$out/variant.o"
# the AVX2 copy (isa=2 with trv=1)
g++ -std=c++20 -O3 -mavx2 -mfma -mbmi -mbmi2 -mlzcnt -ffp-contract=off -DRV_AVX2 -I"$src" -DRV_VARIANT_INL="\"$inl\"" $RV_CXXFLAGS \
    -c "$here/variant_avx512.cpp" -o "$out/variant_avx2.o"
g++ -std=c++20 -O2 -I"$src" "$here/bvh_bench.cpp" "$out/variant.o" "$out/variant_avx2.o" "$build/librayvec.a" -ltinyobjloader -lOpenImageIO -lOpenImageIO_Util -lembree3 -lgmpxx -lgmp -fopenmp \
    -o "$out/bvh_bench"
echo "built $out/bvh_bench"
