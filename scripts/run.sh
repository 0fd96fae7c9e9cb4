#!/usr/bin/env bash
# Quick start, command 1: builds rayvec from a fresh clone and runs the main job: renders the default
# scene (a Whitted-1980-style mirror sphere and hollow glass sphere over a checkerboard) to
# out/whitted.png and prints the effects plan and ray statistics.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
mkdir -p "$root/out"
"$root/build/rayvec" render "$root/scenes/whitted.json" -o "$root/out/whitted.png" --stats
