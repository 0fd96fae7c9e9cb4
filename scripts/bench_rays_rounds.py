#!/usr/bin/env python3
"""Compares rayvec binaries or option sets against Embree in alternating rounds: the measurement the
Decisions of docs/benchmarks.md rest on where single runs swing more than the change being measured.

    scripts/bench_rays_rounds.py ROUNDS MESH.obj "COMMON OPTIONS" NAME=BINARY[|OPTIONS] ...

Each round runs `BINARY bench rays MESH --vs-embree --json --threads 1 --builds 1 COMMON OPTIONS` once
per variant, in a shuffled order. Per ray set it prints, for each variant, the median over rounds of
its ratio to Embree and of that ratio relative to the first variant's in the same round (`rel`): a
slow phase of the machine moves every variant of a round alike, so `rel` cancels it.

Example (two option sets of one binary, AVX2 against Embree AVX2):
    scripts/bench_rays_rounds.py 6 sphere4k.obj "--isa avx2" \\
        two=build/rayvec "one=build/rayvec|--max-leaf 8 --leaf-block 8"
"""
import json
import random
import shlex
import statistics
import subprocess
import sys

SETS = ("primary", "primary_packet", "shadow", "shadow_packet", "incoherent")


def ratios(binary, mesh, options):
    out = subprocess.run([binary, "bench", "rays", mesh, "--vs-embree", "--json", "--threads", "1",
                          "--builds", "1"] + options, check=True, capture_output=True, text=True).stdout
    d = json.loads(out)
    return {k: d[k]["mrays_per_s"] / d["embree"][k]["mrays_per_s"] for k in SETS if k in d}


def main():
    if len(sys.argv) < 5 or not sys.argv[1].isdigit():
        sys.exit(__doc__)
    rounds, mesh, common = int(sys.argv[1]), sys.argv[2], shlex.split(sys.argv[3])
    variants = []
    for arg in sys.argv[4:]:
        name, _, spec = arg.partition("=")
        binary, _, options = spec.partition("|")
        if not name or not binary:
            sys.exit(f"bench_rays_rounds.py: '{arg}' is not NAME=BINARY[|OPTIONS]")
        variants.append((name, binary, common + shlex.split(options)))
    results = {name: [] for name, _, _ in variants}
    for _ in range(rounds):
        for name, binary, options in random.sample(variants, len(variants)):
            results[name].append(ratios(binary, mesh, options))
    base = results[variants[0][0]]
    print(f"{mesh}: {rounds} rounds; per set: median ratio to Embree, and `rel` to {variants[0][0]}")
    for name, _, _ in variants:
        cells = []
        for k in SETS:
            if any(k not in r for rs in results.values() for r in rs):
                continue  # a set some binary does not have
            ratio = statistics.median(r[k] for r in results[name])
            rel = statistics.median(r[k] / b[k] for r, b in zip(results[name], base))
            cells.append(f"{k} {ratio:.3f} rel {rel:.3f}")
        print(f"{name:10s} " + "  ".join(cells))


if __name__ == "__main__":
    main()
