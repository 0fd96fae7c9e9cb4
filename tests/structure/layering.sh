#!/usr/bin/env bash
# Checks the layering of docs/architecture.md on the sources: each folder of src/ (and shaders/)
# includes project headers only from the folders its layer may see, so the core (math, geometry,
# rays, simd, platform, kernels, bvh, accel) never reaches up into the loaders, the renderer, images,
# io or the front end; the CUDA backend (gpu) sits on the core, below bench and the front end;
# and only the SIMD layer (src/simd/, src/bvh/simd/) includes <immintrin.h>.
# Usage: layering.sh REPOSITORY_ROOT
set -euo pipefail
root="$1"
core="math geometry rays simd platform kernels bvh accel"
declare -A allowed=(
  [math]="math"
  [geometry]="math geometry"
  [rays]="math geometry rays"
  [simd]="simd platform"
  [platform]="platform"
  [kernels]="math geometry rays simd platform kernels"
  [bvh]="math geometry rays simd platform kernels bvh"
  [accel]="$core"
  [gpu]="$core gpu"
  [io]="$core io"
  [image]="$core io image"
  [scene]="$core io image scene"
  [shaders]="$core io image scene shaders"
  [render]="$core io image scene shaders render"
  [bench]="$core io gpu bench"
  [accuracy]="$core io gpu bench accuracy"
  [distributed]="$core io image scene shaders render gpu bench distributed"
  [app]="$core io image scene shaders render gpu bench accuracy distributed app"
)
status=0
checked=0
for dir in "$root"/src/*/ "$root"/shaders/; do
  layer=$(basename "$dir")
  if [[ -z "${allowed[$layer]+x}" ]]; then
    echo "FAIL: $dir is not a known layer (add it to ${BASH_SOURCE[0]} and docs/architecture.md)"
    status=1
    continue
  fi
  while IFS= read -r -d '' file; do
    checked=$((checked + 1))
    while IFS= read -r inc; do
      top=${inc%%/*}
      if [[ " ${allowed[$layer]} " != *" $top "* ]]; then
        echo "FAIL: ${file#"$root"/} (layer $layer) includes \"$inc\""
        status=1
      fi
    done < <(sed -n -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]+"([^"]+)".*/\1/p' "$file" | grep / || true)
    if grep -q -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*<immintrin\.h>' "$file" &&
       [[ "$file" != "$root"/src/simd/* && "$file" != "$root"/src/bvh/simd/* ]]; then
      echo "FAIL: ${file#"$root"/} includes <immintrin.h> outside the SIMD layer"
      status=1
    fi
  done < <(find "$dir" -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.inl' -o -name '*.cu' -o -name '*.cuh' \) -print0)
done
echo "checked $checked files"
if [[ $checked -eq 0 ]]; then echo "FAIL: no sources under $root/src"; exit 1; fi
exit $status
