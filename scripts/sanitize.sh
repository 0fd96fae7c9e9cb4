#!/usr/bin/env bash
# Builds rayvec and its tests with AddressSanitizer + UndefinedBehaviorSanitizer (RelWithDebInfo,
# any UB report is fatal) into build-sanitize/ and runs the whole test suite under them (no test
# needed a reduced size). Extra arguments go to ctest: .ci/run passes -E / to skip the
# value-parameterized ISA x intersector instances, which are most of the suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RAYVEC_SANITIZE_BUILD:-$root/build-sanitize}"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"

"$root/scripts/install-deps.sh"
# -O1: half the compile time of -O2 (the heavily inlined ISA units most of all) for the same test
# time under the sanitizers; -g1: line tables only, enough for file:line in every report, and a
# third less compile time than -g (CI's budget: docs/reliability.md)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DRAYVEC_CUDA=OFF -DRAYVEC_MPI=OFF >/dev/null
cmake --build "$build" -j "$(nproc)"

# halt_on_error: the first report fails the test; leaks fail it too (suppressions, if ever needed
# for a third-party library, go in tests/sanitizer_suppressions.txt).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizer_suppressions.txt:${LSAN_OPTIONS:-}"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
