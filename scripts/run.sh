#!/usr/bin/env bash
# Quick start, command 1: builds rayvec from a fresh clone and runs the main job.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
"$root/build/rayvec" bench paper --quick
