#!/usr/bin/env python3
"""Converts a rayvec scene (JSON, with its OBJ/MTL models) to POV-Ray 3.7 scene language, so that
the two renderers can be timed on the same picture (docs/benchmarks.md, "Whole process").

    python3 scripts/scene_to_pov.py scenes/whitted.json out/whitted.pov [--spp 1]
    povray +Iout/whitted.pov +Oout/whitted_pov.png +W640 +H480 -A +WT1 -D File_Gamma=sRGB

What maps exactly: triangles (after the scene's scale, rotation and translation, computed here),
smooth normals, the pinhole camera (right-handed: `right -x`), point lights with I/r² fall-off
(fade_power 2 with a tiny fade_distance), directional lights, the Lambertian term Kd/π (diffuse 1/π),
the ambient term Ka·ambient, mirror reflection weighted by Ks, Fresnel mirrors and Fresnel glass
(interior ior Ni, transmission filtered by Tf), max_depth (max_trace_level = max_depth + 1) and
min_contribution (adc_bailout).

What does not map exactly (named in docs/benchmarks.md): POV-Ray's highlight is not multiplied by
cosθ of the light and its `specular` is one number (the mean of Ks is used, scaled by rayvec's
normalisation (Ns+8)/(8π)); glass lets POV-Ray's shadow rays through (filtered), while rayvec's glass
casts opaque shadows as in Whitted (1980) — a shadow-only copy of each glass object stands in;
POV-Ray's ambient and emission multiply the pigment, so Ka is divided by Kd where Kd > 0 (and dropped
where Kd = 0); textures (map_Kd) are dropped.
"""
import argparse
import json
import math
import os
import sys


def parse_mtl(path):
    materials, current = {}, None
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            parts = line.split()
            if not parts or parts[0].startswith("#"):
                continue
            key, values = parts[0], parts[1:]
            if key == "newmtl":
                current = materials.setdefault(" ".join(values), default_material())
            elif current is not None and key in ("Ka", "Kd", "Ks", "Ke", "Tf"):
                v = [float(x) for x in values[:3]]
                current[key] = v if len(v) == 3 else [v[0]] * 3
            elif current is not None and key in ("Ns", "Ni", "d"):
                current[key] = float(values[0])
            elif current is not None and key == "illum":
                current[key] = int(values[0])
    return materials


def default_material():
    return {"Ka": [0, 0, 0], "Kd": [0.8, 0.8, 0.8], "Ks": [0, 0, 0], "Ke": [0, 0, 0],
            "Tf": [0, 0, 0], "Ns": 0.0, "Ni": 1.0, "d": 1.0, "illum": 1}


def parse_obj(path):
    """Triangles (fans for polygons) grouped by material name: {name: [(v0, v1, v2, n0, n1, n2)]}."""
    base = os.path.dirname(path)
    verts, norms, groups, materials = [], [], {}, {}
    current = ""
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("v "):
                verts.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("vn "):
                norms.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                corners = []
                for token in line.split()[1:]:
                    fields = token.split("/")
                    vi = int(fields[0])
                    vi = vi - 1 if vi > 0 else len(verts) + vi
                    ni = None
                    if len(fields) > 2 and fields[2]:
                        ni = int(fields[2])
                        ni = ni - 1 if ni > 0 else len(norms) + ni
                    corners.append((vi, ni))
                tris = groups.setdefault(current, [])
                for k in range(1, len(corners) - 1):
                    tris.append((corners[0], corners[k], corners[k + 1]))
            elif line.startswith("usemtl"):
                current = line.split(maxsplit=1)[1].strip() if len(line.split()) > 1 else ""
            elif line.startswith("mtllib"):
                name = line.split(maxsplit=1)[1].strip()
                mtl = os.path.join(base, name)
                if os.path.isfile(mtl):
                    materials.update(parse_mtl(mtl))
    return verts, norms, groups, materials


def rotation(deg):
    """scale, then rotation about x, then y, then z (right-handed), as rayvec's transform.cpp."""
    ax, ay, az = (math.radians(d) for d in deg)

    def rx(a): return [[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]
    def ry(a): return [[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]]
    def rz(a): return [[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]
    def mul(a, b): return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(rz(az), mul(ry(ay), rx(ax)))


def apply(m, v):
    return [m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] for i in range(3)]


def vec(v):
    return f"<{v[0]:.9g},{v[1]:.9g},{v[2]:.9g}>"


def finish(mat):
    kd, ka, ks = mat["Kd"], mat["Ka"], mat["Ks"]
    illum, ns = mat["illum"], max(mat["Ns"], 1e-3)
    ambient = [ka[i] / kd[i] if kd[i] > 0 else 0 for i in range(3)]
    out = [f"ambient rgb {vec(ambient)}", f"diffuse {1 / math.pi:.9g}"]
    if illum >= 2 and max(ks) > 0:
        out.append(f"specular {sum(ks) / 3 * (ns + 8) / (8 * math.pi):.9g} roughness {1 / ns:.9g}")
    if illum in (3, 4, 6) and max(ks) > 0:
        out.append(f"reflection {{ rgb {vec(ks)} }}")
    if illum in (5, 7) and max(ks) > 0:
        out.append(f"reflection {{ 0, rgb {vec(ks)} fresnel on }} conserve_energy")
    return "finish { " + " ".join(out) + " }"


def material_block(mat):
    glass = mat["illum"] in (6, 7) and max(mat["Tf"]) > 0
    if glass:
        pigment = f"pigment {{ rgbf <{mat['Tf'][0]:.9g},{mat['Tf'][1]:.9g},{mat['Tf'][2]:.9g},1> }}"
        interior = f"interior {{ ior {mat['Ni']:.9g} }}"
        return f"{pigment} {finish(mat)} {interior}", True
    if mat["illum"] == 5:
        return f"pigment {{ rgb {vec(mat['Kd'])} }} {finish(mat)} interior {{ ior {mat['Ni']:.9g} }}", False
    return f"pigment {{ rgb {vec(mat['Kd'])} }} {finish(mat)}", False


def write_mesh(out, name, tris, verts, norms, m, translate, nm):
    used_v, used_n = {}, {}
    for tri in tris:
        for vi, ni in tri:
            used_v.setdefault(vi, len(used_v))
            if ni is not None:
                used_n.setdefault(ni, len(used_n))
    smooth = len(used_n) > 0 and all(ni is not None for tri in tris for _, ni in tri)
    out.write(f"#declare {name} = mesh2 {{\n  vertex_vectors {{ {len(used_v)},\n")
    out.write(",\n".join(vec([a + b for a, b in zip(apply(m, verts[vi]), translate)]) for vi in used_v))
    out.write("\n  }\n")
    if smooth:
        out.write(f"  normal_vectors {{ {len(used_n)},\n")
        out.write(",\n".join(vec(apply(nm, norms[ni])) for ni in used_n))
        out.write("\n  }\n")
    out.write(f"  face_indices {{ {len(tris)},\n")
    out.write(",\n".join(f"<{used_v[a[0]]},{used_v[b[0]]},{used_v[c[0]]}>" for a, b, c in tris))
    out.write("\n  }\n")
    if smooth:
        out.write(f"  normal_indices {{ {len(tris)},\n")
        out.write(",\n".join(f"<{used_n[a[1]]},{used_n[b[1]]},{used_n[c[1]]}>" for a, b, c in tris))
        out.write("\n  }\n")
    out.write("}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", help="rayvec scene JSON")
    ap.add_argument("pov", help="POV-Ray file to write")
    args = ap.parse_args()
    with open(args.scene, encoding="utf-8") as f:
        scene = json.load(f)
    base = os.path.dirname(os.path.abspath(args.scene))
    cam = scene["camera"]
    render = scene.get("render", {})
    width, height = cam.get("width", 640), cam.get("height", 480)
    aspect = width / height
    fov_x = 2 * math.degrees(math.atan(math.tan(math.radians(cam.get("fov_y", 45)) / 2) * aspect))
    out = open(args.pov, "w", encoding="utf-8")
    out.write(f"// Written by scripts/scene_to_pov.py from {os.path.basename(args.scene)}\n#version 3.7;\n")
    out.write("global_settings { assumed_gamma 1.0 ambient_light rgb <1,1,1>"
              f" max_trace_level {render.get('max_depth', 8) + 1}"
              f" adc_bailout {render.get('min_contribution', 0.01):.9g} }}\n")
    out.write(f"background {{ rgb {vec(scene.get('background', [0, 0, 0]))} }}\n")
    out.write(f"camera {{ perspective location {vec(cam['eye'])} right -x*{aspect:.9g} up y"
              f" sky {vec(cam.get('up', [0, 1, 0]))} angle {fov_x:.9g} look_at {vec(cam['look_at'])} }}\n")
    ambient = scene.get("ambient", [0, 0, 0])
    fade = 1e-3
    for light in scene.get("lights", []):
        if light.get("type", "point") == "point":
            colour = [x / (2 * fade * fade) for x in light["intensity"]]
            out.write(f"light_source {{ {vec(light['position'])} rgb {vec(colour)}"
                      f" fade_distance {fade} fade_power 2 }}\n")
        else:
            d = light["direction"]
            n = math.sqrt(sum(x * x for x in d))
            far = [-x / n * 1e6 for x in d]
            out.write(f"light_source {{ {vec(far)} rgb {vec(light['irradiance'])} parallel point_at <0,0,0> }}\n")
    mesh_id = 0
    for obj in scene["objects"]:
        verts, norms, groups, materials = parse_obj(os.path.join(base, obj["obj"]))
        t = obj.get("transform", {})
        s = t.get("scale", 1)
        s = [s, s, s] if not isinstance(s, list) else s
        r = rotation(t.get("rotate_deg", [0, 0, 0]))
        m = [[r[i][j] * s[j] for j in range(3)] for i in range(3)]
        nm = [[r[i][j] / s[j] for j in range(3)] for i in range(3)]
        translate = t.get("translate", [0, 0, 0])
        for mat_name, tris in groups.items():
            mat = dict(materials.get(mat_name, default_material()))
            mat.update({k: v for k, v in obj.get("material", {}).items() if k != "map_Kd"})
            mat["Ka"] = [mat["Ka"][i] * ambient[i] for i in range(3)]
            name = f"M{mesh_id}"
            mesh_id += 1
            write_mesh(out, name, tris, verts, norms, m, translate, nm)
            block, glass = material_block(mat)
            out.write(f"object {{ {name} {block} }}\n")
            if glass:  # rayvec's glass blocks shadow rays: an opaque copy seen only by them
                out.write(f"object {{ {name} pigment {{ rgb 0 }} no_image no_reflection }}\n")
    out.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
