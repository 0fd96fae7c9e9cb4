#!/usr/bin/env bash
# Regenerates every picture (and the trace listing) of docs/tutorial.md by running the commands the
# tutorial shows: each line of its ```sh blocks that starts with `rayvec ` is run from the repository
# root with build/rayvec, so the pictures are exactly what those commands make.
# Usage: scripts/make_tutorial_images.sh [path/to/rayvec]   (default build/rayvec; build it first)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rayvec="$(realpath "${1:-$root/build/rayvec}")"
cd "$root"
[[ -x "$rayvec" ]] || { echo "make_tutorial_images.sh: no rayvec at $rayvec (build it: ./scripts/run.sh)" >&2; exit 2; }
mkdir -p docs/images/tutorial
count=0
while IFS= read -r line; do
  echo "+ $line"
  bash -c "set -euo pipefail; ${line/#rayvec /\"$rayvec\" }"
  count=$((count + 1))
done < <(awk '/^```sh$/ {on = 1; next} /^```$/ {on = 0} on && /^rayvec / {print}' docs/tutorial.md)
[[ $count -gt 0 ]] || { echo "make_tutorial_images.sh: no rayvec commands found in docs/tutorial.md" >&2; exit 1; }
echo "ran $count commands; pictures in docs/images/tutorial/"
