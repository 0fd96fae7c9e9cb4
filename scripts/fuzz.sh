#!/usr/bin/env bash
# Builds the libFuzzer harnesses of tests/fuzz/ (clang-14, ASan + UBSan) into build-fuzz/ and runs
# each one for SECONDS (default 10) seconds, one after another, starting from the seed corpus in
# tests/data/fuzz_corpus/<target>/ (the corpus grown by earlier runs is kept in build-fuzz/corpus/).
# Exits non-zero at the first crash, leak, hang (-timeout) or sanitizer report, naming the
# reproducer file; turn it into a regression test under tests/data/ (see docs/reliability.md).
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   targets: obj mtl scene_json rays_csv visibility_csv image
#        scripts/fuzz.sh --runs N [TARGET...]      each target runs exactly N executions (no time
#                                                  limit): the long runs of docs/reliability.md
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
limit=()
if [[ "${1:-}" == "--runs" ]]; then
  [[ "${2:-}" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh --runs N [TARGET...]" >&2; exit 2; }
  limit=(-runs="$2")
  what="$2 runs"
  shift 2
else
  seconds="${1:-10}"
  shift || true
  limit=(-max_total_time="$seconds")
  what="${seconds} s"
fi
targets=("$@")
((${#targets[@]})) || targets=(obj mtl scene_json rays_csv visibility_csv image)
build="${RAYVEC_FUZZ_BUILD:-$root/build-fuzz}"

"$root/scripts/install-deps.sh" --with-fuzz
# -g1: line tables only (file:line in reports), a third less compile time than -g
cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" >/dev/null
cmake --build "$build" -j "$(nproc)"

# The harnesses write their input to files here (memory-backed when /dev/shm exists).
scratch=$(mktemp -d /dev/shm/rayvec-fuzz-XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export RAYVEC_FUZZ_SCRATCH="$scratch"

for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  artifacts="$build/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  log="$build/fuzz_$t.log"
  # -timeout: an input taking more than 10 s counts as a hang; -rss_limit_mb: as a memory bomb.
  start=$SECONDS
  if ! "$build/fuzz_$t" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$artifacts/" \
       "$corpus" "$root/tests/data/fuzz_corpus/$t" >"$log" 2>&1; then
    grep -E "ERROR|SUMMARY|Test unit written" "$log" >&2 || tail -20 "$log" >&2
    echo "fuzz: $t FAILED (log: $log)" >&2
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: //p' "$log")
  echo "fuzz: $t ok, $runs runs in $((SECONDS - start)) s (limit: $what)"
done
