#!/usr/bin/env bash
# Checks the runtime-dispatch rule on the built libraries given as arguments: an ISA unit (*_avx2.cpp, *_avx512.cpp) may only
# define weak (inline/template) symbols inside its own namespace rayvec::<isa>. A weak symbol outside it
# (say std::min<float> or a shared header's inline function) could be picked by the linker for baseline
# callers and crash CPUs without that ISA. DW.ref.__gxx_personality_v0 (a data word pointing at the C++
# exception personality routine, emitted weak by some builds, e.g. with -fsanitize=address) holds no
# code and is the same in every unit, so it is allowed.
set -euo pipefail
status=0
checked=0
for lib in "$@"; do
for member in $(ar t "$lib" | grep -E '_(avx2|avx512)\.cpp\.o$' || true); do
  isa=$(echo "$member" | sed -E 's/.*_(avx2|avx512)\.cpp\.o$/\1/')
  checked=$((checked + 1))
  # nm on an archive prints a "member:" header before each member's symbols.
  bad=$(nm -C --defined-only "$lib" | awk -v hdr="$member:" '
      $0 == hdr {inside=1; next} /\.o:$/ {inside=0} inside' |
        awk '$2 ~ /^[WVu]$/' | grep -v -E "^[0-9a-f]+ [WVu] ([a-z_:<>, ]+ )?rayvec::${isa}::" |
        grep -v -E "^[0-9a-f]+ V DW\.ref\.__gxx_personality_v0$" || true)
  if [[ -n "$bad" ]]; then
    echo "FAIL: $member defines weak symbols outside rayvec::$isa:"
    echo "$bad"
    status=1
  fi
done
done
echo "checked $checked ISA units"
if [[ $checked -eq 0 ]]; then echo "FAIL: no ISA units found in $*"; exit 1; fi
exit $status
