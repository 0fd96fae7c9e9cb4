#!/usr/bin/env python3
"""Writes the scene of `rayvec bench paper` as files `rayvec hits` reads (deterministic, bit for bit).

    scripts/make_paper_scene.py MESH.obj RAYS.csv [--triangles N] [--side S]

N triangles whose vertices are uniform in the unit cube, drawn from SplitMix64 with the seed of
src/bench/paper_scene.cpp, and S × S pinhole-camera rays from (0.5, 0.5, -1.5) through the cube's
front face, ray index j·S + i — the same floats as paper_triangles and paper_camera_rays, so
`rayvec hits` traces exactly the work of a `bench paper` row. Defaults: Table 1's mod2 (50,000
triangles, 200 × 200 = 40,000 rays). Floats are printed with 9 significant digits, which read back
to the same float.
"""
import argparse
import math
import struct

MASK = (1 << 64) - 1
SEED = 0x5E4A2018


def splitmix64(state):
    while True:
        state = (state + 0x9E3779B97F4A7C15) & MASK
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        yield z ^ (z >> 31)


def to_float(x):
    """x rounded to the nearest float (binary32), as a Python float."""
    return struct.unpack("f", struct.pack("f", x))[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mesh")
    ap.add_argument("rays")
    ap.add_argument("--triangles", type=int, default=50000)
    ap.add_argument("--side", type=int, default=200)
    a = ap.parse_args()
    if a.triangles < 1 or a.side < 1:
        ap.error("need --triangles >= 1 and --side >= 1")
    rng = splitmix64(SEED)
    lines = ["# rayvec bench paper scene: %d triangles\n" % a.triangles]
    for _ in range(3 * a.triangles):
        x, y, z = ((next(rng) >> 40) * 2.0**-24 for _ in range(3))
        lines.append("v %.9g %.9g %.9g\n" % (x, y, z))
    for t in range(a.triangles):
        lines.append("f %d %d %d\n" % (3 * t + 1, 3 * t + 2, 3 * t + 3))
    with open(a.mesh, "w") as f:
        f.writelines(lines)

    s = a.side
    lines = ["ox,oy,oz,dx,dy,dz\n"]
    for j in range(s):
        for i in range(s):
            d = ((i + 0.5) / s - 0.5, (j + 0.5) / s - 0.5, 1.5)
            n = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
            dx, dy, dz = (to_float(c / n) for c in d)
            lines.append("0.5,0.5,-1.5,%.9g,%.9g,%.9g\n" % (dx, dy, dz))
    with open(a.rays, "w") as f:
        f.writelines(lines)


if __name__ == "__main__":
    main()
