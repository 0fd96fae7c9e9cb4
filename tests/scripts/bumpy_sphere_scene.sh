#!/usr/bin/env bash
# The large scene of docs/benchmarks.md's whole-process comparison is made by its own command:
# make_bumpy_sphere.py --scene writes a scene that `rayvec render` renders (the sphere in part of the
# picture, background around it) and that scene_to_pov.py converts for POV-Ray.
# Usage: bumpy_sphere_scene.sh REPOSITORY_ROOT RAYVEC
set -euo pipefail
root="$1"
rayvec="$2"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/meshes"
python3 "$root/scripts/make_bumpy_sphere.py" "$scratch/meshes/sphere.obj" --rings 16 --segments 32 \
  --scene "$scratch/sphere.json"
stats=$("$rayvec" render "$scratch/sphere.json" --width 32 --height 24 --threads 1 -q --stats -o "$scratch/sphere.png")
test -s "$scratch/sphere.png"
# the sphere covers part of the picture: some primary rays hit it and send a shadow ray, not all
read -r primary shadow < <(echo "$stats" | sed -n 's/^rays: \([0-9]*\) primary, \([0-9]*\) shadow.*/\1 \2/p')
echo "primary rays $primary, shadow rays $shadow"
((primary == 32 * 24 && shadow > primary / 10 && shadow < primary))
python3 - "$scratch" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1] + "/sphere.json"))
assert scene["objects"][0]["obj"] == "meshes/sphere.obj", scene["objects"][0]["obj"]
assert len(scene["lights"]) == 1 and scene["camera"]["width"] == 640
PY
python3 "$root/scripts/scene_to_pov.py" "$scratch/sphere.json" "$scratch/sphere.pov"
grep -q "mesh2" "$scratch/sphere.pov"
grep -q "light_source" "$scratch/sphere.pov"
echo "ok: scene written, rendered and converted"
