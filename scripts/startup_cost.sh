#!/usr/bin/env bash
# Start-up cost of the rayvec binary: for each command below, over RUNS runs (default 30) of the whole
# process, the median wall time, the mean CPU time (perf stat task-clock, when perf works) and the
# largest resident set (RSS, /usr/bin/time). Wall time follows the load of the machine; CPU time
# much less.
# The --help forms stop before reading any input, so they measure what the binary pays to start (the
# dynamic loader, shared libraries, static initializers); `render` is a whole 16x16 one-cube render.
# Usage: scripts/startup_cost.sh [RUNS] [BINARY]      docs/benchmarks.md#decision-image-io-without-openimageio
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-30}"
bin="${2:-$root/build/rayvec}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cat >"$scratch/cube.json" <<JSON
{ "camera": { "eye": [2, 1.5, 3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_y": 45, "width": 16, "height": 16 },
  "lights": [ { "type": "point", "position": [3, 4, 2], "intensity": [20, 20, 20] } ],
  "objects": [ { "obj": "$root/scenes/models/cube.obj", "material": { "Kd": [0.8, 0.3, 0.2], "illum": 1 } } ] }
JSON

measure() {  # measure LABEL ARGS...: LABEL, median wall ms, CPU ms (perf task-clock), largest RSS MB
  local label="$1"
  shift
  local times=() rss=0 t0 t1 m cpu="-"
  for ((i = 0; i < runs; ++i)); do
    t0=$EPOCHREALTIME
    "$bin" "$@" >/dev/null 2>&1 || true
    t1=$EPOCHREALTIME
    times+=("$(echo "($t1 - $t0) * 1000" | bc -l)")
    /usr/bin/time -f '%M' -o "$scratch/t" "$bin" "$@" >/dev/null 2>&1 || true
    m=$(tail -1 "$scratch/t")
    ((m > rss)) && rss=$m
  done
  if command -v perf >/dev/null && perf stat -x, -e task-clock true >/dev/null 2>&1; then
    cpu=$(perf stat -x, -e task-clock -r "$runs" "$bin" "$@" 2>&1 >/dev/null | awk -F, '/task-clock/ {printf "%.1f", $1}')
  fi
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((runs + 1) / 2))p")
  printf '%-44s %7.1f ms wall %7s ms CPU %6.1f MB RSS\n' "$label" "$median" "$cpu" "$(echo "$rss / 1024" | bc -l)"
}

echo "binary: $bin ($runs runs each)"
measure "rayvec --help" --help
measure "rayvec info" info
measure "rayvec hits --help" hits --help
measure "rayvec visibility --help" visibility --help
measure "rayvec bench paper --help" bench paper --help
measure "rayvec compare --help" compare --help
measure "rayvec render cube.json (16x16) -o cube.png" render "$scratch/cube.json" -o "$scratch/cube.png"
echo "shared libraries at start: $(ldd "$bin" | wc -l)"
