#!/usr/bin/env python3
"""Writes an OBJ's vertices and triangles in the format `rayvec visibility` reads (for benchmarks).

    scripts/obj_to_visibility.py MESH.obj VERTS.csv FACES.csv

VERTS.csv: one `x,y,z` row per `v` line; FACES.csv: one row per triangle (polygons as fans), three
0-based vertex rows written as floats, as in the CUDA visibility study's files.
"""
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    verts, faces = [], []
    with open(sys.argv[1]) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                verts.append(",".join(w[1:4]))
            elif w[0] == "f":
                idx = [int(x.split("/")[0]) for x in w[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                for k in range(2, len(idx)):
                    faces.append("%.1f,%.1f,%.1f" % (idx[0], idx[k - 1], idx[k]))
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(verts) + "\n")
    with open(sys.argv[3], "w") as f:
        f.write("\n".join(faces) + "\n")


if __name__ == "__main__":
    main()
