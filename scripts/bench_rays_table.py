#!/usr/bin/env python3
"""Runs `rayvec bench rays --vs-embree --json` several times per mesh and thread count and prints the
median of each number as a Markdown table like those of docs/benchmarks.md ("Current results").

    scripts/bench_rays_table.py RAYVEC_BINARY MESH.obj [MESH.obj ...] [--threads 1 2] [--runs 3]
                                [--size 1024x1024] [--isa avx2] [--builds 5]

--isa passes that ISA to rayvec, which caps Embree at it too (AVX2 against AVX2).

Medians over runs, because other processes share the machine: every ratio is taken inside one run
(rayvec and Embree trace the same rays back to back) and the median of those ratios is printed.
The thread counts of a mesh are interleaved round by round (1, 2, 1, 2, ...), and the 2-thread build
speedup is the median of the per-round ratios, so both builds of a ratio share the VM's phase.
"""
import argparse
import json
import os
import statistics
import subprocess

SETS = [("primary", "rtcIntersect1"), ("primary_packet", "rtcIntersect16"),
        ("shadow", "rtcOccluded1"), ("shadow_packet", "rtcOccluded16"), ("incoherent", "rtcIntersect1")]


def run(binary, mesh, threads, size, isa, builds):
    extra = (["--isa", isa] if isa else []) + ["--builds", str(builds)]
    out = subprocess.run([binary, "bench", "rays", mesh, "--vs-embree", "--json", "--threads",
                          str(threads), "--size", size] + extra, check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("binary")
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--size", default="1024x1024")
    ap.add_argument("--isa", default="", help="rayvec --isa (default: the best this CPU has)")
    ap.add_argument("--builds", type=int, default=5, help="builds per run, median reported (bench rays --builds)")
    a = ap.parse_args()
    med = statistics.median
    print("| mesh | triangles | threads | set (Embree call) | rayvec Mrays/s | Embree Mrays/s | ratio | id mismatches |")
    print("|---|---:|---:|---|---:|---:|---:|---:|")
    builds = []
    speedups = {}
    fma = []
    for mesh in a.meshes:
        by_threads = {t: [] for t in a.threads}
        for _ in range(a.runs):  # interleaved: every round runs each thread count once
            for t in a.threads:
                by_threads[t].append(run(a.binary, mesh, t, a.size, a.isa, a.builds))
                if "fma_per_cycle" in by_threads[t][-1]:
                    fma.append(by_threads[t][-1]["fma_per_cycle"])
        name = os.path.basename(mesh)
        if 1 in by_threads and 2 in by_threads:
            pairs = list(zip(by_threads[1], by_threads[2]))
            speedups[name] = (med(p[0]["build_s"] / p[1]["build_s"] for p in pairs),
                              med(p[0]["embree"]["build_s"] / p[1]["embree"]["build_s"] for p in pairs))
        for t in a.threads:
            runs = by_threads[t]
            r0 = runs[0]
            name = os.path.basename(mesh)
            for key, call in SETS:
                ours = med(r[key]["mrays_per_s"] for r in runs)
                theirs = med(r["embree"][key]["mrays_per_s"] for r in runs)
                ratio = med(r[key]["mrays_per_s"] / r["embree"][key]["mrays_per_s"] for r in runs)
                mism = max(r["embree"]["mismatches"][key] for r in runs)
                print(f"| {name} | {r0['triangles']} | {t} | {key} ({call}) | {ours:.2f} | {theirs:.2f} "
                      f"| {ratio:.2f}x | {mism} of {r0[key]['rays']} |")
            builds.append((name, r0["triangles"], t, med(r["build_s"] for r in runs),
                           med(r["embree"]["build_s"] for r in runs), r0["bytes_per_tri"],
                           r0["isa"], r0["cpu"]))
    print()
    print("| mesh | triangles | threads | rayvec build s | Embree HIGH build s | rayvec/Embree time | bytes/triangle |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, tris, t, ours, theirs, bpt, isa, cpu in builds:
        print(f"| {name} | {tris} | {t} | {ours:.4f} | {theirs:.4f} | {ours / theirs:.2f} | {bpt:.1f} |")
    print()
    for name, (ours, theirs) in speedups.items():
        print(f"- {name}: 2-thread build speedup (median of per-round ratios) rayvec {ours:.2f}x, "
              f"Embree {theirs:.2f}x")
    print(f"- isa {builds[0][6]}, cpu {builds[0][7]}, median of {a.runs} runs of the command")
    if fma:  # absent from the output of rayvec binaries older than the probe
        v2, v512 = med(f["avx2"] for f in fma), med(f["avx512"] for f in fma)
        half = " (512-bit operations at half rate on this host)" if 0 < v512 < 0.7 * v2 else ""
        print(f"- vector FMAs per cycle (median over runs): avx2 {v2:.2f}, avx512 {v512:.2f}{half}")


if __name__ == "__main__":
    main()
