#!/usr/bin/env bash
# Start-up cost of the rayvec binary: for each command below, the median wall time and the largest
# resident set (RSS) over RUNS runs (default 30), measured with /usr/bin/time around the whole process.
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

measure() {  # measure LABEL ARGS...: prints LABEL, median seconds, max RSS in MB
  local label="$1"
  shift
  local times=() rss=0
  for ((i = 0; i < runs; ++i)); do
    /usr/bin/time -f '%e %M' -o "$scratch/t" "$bin" "$@" >/dev/null 2>&1 || true
    read -r t m <"$scratch/t"
    times+=("$t")
    ((m > rss)) && rss=$m
  done
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((runs + 1) / 2))p")
  printf '%-44s %6.3f s %6.1f MB\n' "$label" "$median" "$(echo "$rss / 1024" | bc -l)"
}

echo "binary: $bin ($runs runs each; median time, largest RSS)"
measure "rayvec --help" --help
measure "rayvec info" info
measure "rayvec hits --help" hits --help
measure "rayvec visibility --help" visibility --help
measure "rayvec bench paper --help" bench paper --help
measure "rayvec compare --help" compare --help
measure "rayvec render cube.json (16x16) -o cube.png" render "$scratch/cube.json" -o "$scratch/cube.png"
echo "shared libraries at start: $(ldd "$bin" | wc -l)"
