#!/usr/bin/env python3
"""Writes a closed, bumpy UV sphere as a Wavefront OBJ for `rayvec bench rays` (deterministic).

    scripts/make_bumpy_sphere.py OUT.obj [--rings R] [--segments S] [--scene OUT.json]

Vertices: r = 1 + 0.05 sin(7θ) sin(9φ) + 0.02 sin(23θ + 1) cos(17φ) on a (R+1) × S grid of polar
angle θ and azimuth φ, poles shared; 2·R·S − 2·S triangles. Defaults give the ~1M-triangle mesh of
docs/benchmarks.md (R = 500, S = 1000: 998,000 triangles); --rings 32 --segments 64 gives the
~4k one (3,968 triangles). Coordinates are printed with 7 significant digits.
--scene also writes a `rayvec render` scene of the sphere (camera, one point light, a diffuse
material; 640x480): the 1M-triangle scene of docs/benchmarks.md's "Whole process", which
scripts/scene_to_pov.py converts for POV-Ray like the scenes in scenes/.
"""
import argparse
import json
import math
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--rings", type=int, default=500)
    ap.add_argument("--segments", type=int, default=1000)
    ap.add_argument("--scene", help="also write a render scene of the sphere to this JSON file")
    a = ap.parse_args()
    R, S = a.rings, a.segments
    if R < 2 or S < 3:
        ap.error("need --rings >= 2 and --segments >= 3")
    lines = ["# bumpy sphere: rings %d segments %d\n" % (R, S), "v 0 1 0\n"]
    for i in range(1, R):
        th = math.pi * i / R
        for j in range(S):
            ph = 2 * math.pi * j / S
            r = 1 + 0.05 * math.sin(7 * th) * math.sin(9 * ph) + 0.02 * math.sin(23 * th + 1) * math.cos(17 * ph)
            lines.append("v %.7g %.7g %.7g\n" % (r * math.sin(th) * math.cos(ph), r * math.cos(th),
                                                  r * math.sin(th) * math.sin(ph)))
    lines.append("v 0 -1 0\n")
    north, south = 1, 2 + (R - 1) * S

    def at(i, j):  # ring i in 1..R-1, OBJ indices are 1-based
        return 2 + (i - 1) * S + (j % S)

    for j in range(S):
        lines.append("f %d %d %d\n" % (north, at(1, j + 1), at(1, j)))
    for i in range(1, R - 1):
        for j in range(S):
            a0, a1, b0, b1 = at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)
            lines.append("f %d %d %d\n" % (a0, a1, b0))
            lines.append("f %d %d %d\n" % (a1, b1, b0))
    for j in range(S):
        lines.append("f %d %d %d\n" % (south, at(R - 1, j), at(R - 1, j + 1)))
    with open(a.out, "w") as f:
        f.writelines(lines)
    if a.scene:
        write_scene(a.scene, a.out, R, S, sum(1 for line in lines if line.startswith("f ")))


def write_scene(path, obj, rings, segments, triangles):
    obj_from_scene = os.path.relpath(os.path.abspath(obj), os.path.dirname(os.path.abspath(path)))
    scene = {
        "comment": "Bumpy sphere of %d triangles (make_bumpy_sphere.py --rings %d --segments %d) "
                   "under one point light: the large scene of the whole-process comparison."
                   % (triangles, rings, segments),
        "camera": {"eye": [0, 0.8, 3.2], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_y": 45,
                   "width": 640, "height": 480},
        "background": [0.05, 0.05, 0.08],
        "lights": [{"type": "point", "position": [3, 4, 5], "intensity": [60, 60, 60]}],
        "objects": [{"obj": obj_from_scene,
                     "material": {"Kd": [0.8, 0.55, 0.3], "illum": 1}}],
        "render": {"max_depth": 1, "spp": 1},
    }
    with open(path, "w") as f:  # one line per key, as the scenes in scenes/
        f.write("{\n" + ",\n".join("  %s: %s" % (json.dumps(k), json.dumps(v)) for k, v in scene.items())
                + "\n}\n")


if __name__ == "__main__":
    main()
