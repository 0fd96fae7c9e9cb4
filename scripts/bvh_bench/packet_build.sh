#!/bin/sh
# Builds packet_bench (packet_bench.cpp) against an existing Release build of librayvec.a, with one
# variant packet traversal per NAME=INL[:CXXFLAGS] argument (INL: a copy of bvh/bvh_packet.inl, or
# "tree" for the tree's own). Not part of the product build.
#   scripts/bvh_bench/packet_build.sh BUILD_DIR fwd=/tmp/fwd.inl lanes4=tree:-DK=4 ...
#   BUILD_DIR/packet_bench/packet_bench /tmp/lead/sphere4k.obj 9
# RV_ISA=avx2 (here and when running packet_bench): AVX2 variants (packet_variant.cpp, -DRV_AVX2).
set -e
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../../src" && pwd)
build=${1:?usage: packet_build.sh BUILD_DIR [NAME=INL[:CXXFLAGS]]...}
shift
out=${OUT:-$build/packet_bench}
mkdir -p "$out"
isa="-mavx2 -mfma -mbmi -mbmi2 -mlzcnt -mf16c -mpopcnt -ffp-contract=off -Wno-maybe-uninitialized"
if [ "${RV_ISA:-avx512}" = avx512 ]; then
  isa="$isa -mavx512f -mavx512dq -mavx512bw -mavx512vl -mavx512cd"
else
  isa="$isa -DRV_AVX2"
fi
objs=""
pids=""
i=0
for spec in "$@"; do
  name=${spec%%=*}
  rest=${spec#*=}
  inl=${rest%%:*}
  flags=""
  case "$rest" in *:*) flags=${rest#*:} ;; esac
  [ "$inl" = tree ] && inl="$src/bvh/bvh_packet.inl"
  g++ -std=c++20 -O3 $isa -I"$src" -DRV_PACKET_INL="\"$inl\"" -DRV_VARIANT_NAME="\"$name\"" \
      -DRV_VARIANT_NS=v$i $flags $RV_CXXFLAGS -c "$here/packet_variant.cpp" -o "$out/v$i.o" &
  pids="$pids $!"
  objs="$objs $out/v$i.o"
  i=$((i + 1))
  if [ $((i % 2)) -eq 0 ]; then for p in $pids; do wait $p; done; pids=""; fi
done
for p in $pids; do wait $p; done  # set -e: a failed compile stops the build
g++ -std=c++20 -O2 -I"$src" "$here/packet_bench.cpp" $objs "$build/librayvec.a" -ltinyobjloader -lOpenImageIO \
    -lOpenImageIO_Util -lembree3 -lgmpxx -lgmp -fopenmp -o "$out/packet_bench"
echo "built $out/packet_bench"
