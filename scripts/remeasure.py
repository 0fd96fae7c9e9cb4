#!/usr/bin/env python3
"""Re-measures on this machine the Decisions of docs/benchmarks.md that were measured on one vendor's
CPUs only (its table "Re-measuring a Decision"): for each, builds the commit the Decision was
measured against and the commit that made it (scripts/build_at.sh, cached under /tmp/rayvec-at) and
runs the Decision's commands with the two as `old` and `new`, in alternating rounds — the change
alone, without what came later (--against-build: this build as `new` instead, everything since the
old commit). Prints Markdown: per Decision, each command and what it measured. Progress goes to
stderr.

    scripts/remeasure.py [--build DIR] [--work DIR] [--only NAME ...] [--list] [--against-build]

  --build DIR   this build (default build/): its `rayvec info` tells the CPU's ISAs
  --work DIR    where the inputs are made the first time and reused (default /tmp/rayvec-targets,
                the folder scripts/targets.py uses)
  --only NAME   only these Decisions (their anchors without "decision-"; --list names them)
  --list        print the Decisions, their commits and commands, and run nothing
  --against-build  `new` is this build, not the Decision's commit

Two kinds of command:
  rays  scripts/bench_rays_rounds.py: `bench rays --vs-embree` of old and new in shuffled order per
        round; per ray set the ratio to Embree and `rel`, new over old in the same round
  cpu   the same rayvec command line with each binary, alternating; the user + system CPU time of
        each whole process (wait4), medians and the median of new / old per round (below 1: new is
        faster)
AVX-512 commands are skipped on a CPU without AVX-512 (`rayvec info`), Embree ones without the
Embree module. Every commit is built first, on every CPU even when the script is pinned (about 1.5 minutes
a commit on two cores, 20 minutes for the whole table), then measured on the pinned core (about half an
hour).
"""
import argparse
import os
import statistics
import subprocess
import sys

import targets  # the work folder's inputs, the ISA and Embree probes, whole-process CPU times
from targets import ASSIMP, ROOT, log

# Meshes the commands name that are not made in --work (targets.Targets makes the others).
FILES = {"WusonOBJ": f"{ASSIMP}/WusonOBJ.obj", "regr01": f"{ASSIMP}/regr01.obj",
         "sphere.obj": f"{ROOT}/scenes/models/sphere.obj"}


def rays(rounds, mesh, options):
    return ("rays", rounds, mesh, options)


def cpu(rounds, args):
    return ("cpu", rounds, None, args)


# (anchor in docs/benchmarks.md, the commit it was measured against, the commit that made it, its
# commands). `{mesh}` in a cpu
# command is that mesh's path, `{mod2.csv}` the paper scene's rays, `{vis}` the verts and faces of
# sphere40k for `rayvec visibility`, `{out}` a scratch output file in --work.
DECISIONS = (
    ("decision-any-hit-leaf-lanes", "0a67d40", "1973db9",
     [rays(6, "WusonOBJ", "--isa avx512 --size 1024x1024"), rays(6, "sphere4k", "--isa avx512 --size 1024x1024"),
      rays(6, "WusonOBJ", "--isa avx2 --size 1024x1024"),
      rays(6, "WusonOBJ", "--isa avx512 --size 1024x1024 --intersector watertight")]),
    ("decision-leaf-block-choice", "4c43890", "ebaa05b",
     [rays(8, "regr01", "--isa avx512 --size 1024x1024"), rays(6, "sphere.obj", "--isa avx512 --size 1024x1024"),
      rays(6, "WusonOBJ", "--isa avx512 --size 1024x1024")]),
    ("decision-one-or-two-children", "4e1cb89", "d08411a",
     [rays(6, "sphere1m", "--isa avx2 --size 1024x1024"), rays(6, "sphere1m", "--isa avx512 --size 1024x1024")]),
    ("decision-packet-slot-cull", "9864796", "1654d97", [rays(4, "sphere4k", "--isa avx512 --size 512x512")]),
    ("decision-crossed-group-test", "428253f", "d5300e4",
     [cpu(4, "bench paper --models mod2 --no-baselines --no-scaling --threads 1 --isa avx512"),
      cpu(4, "hits --mesh {mod2} --rays {mod2.csv} --accel brute --threads 1 --isa avx512 -o {out}"),
      cpu(4, "visibility {vis} --origin 0,0,-3 --accel brute --threads 1 --isa avx512 -o {out}"),
      cpu(4, "visibility {vis} --origin 0,0,-3 --accel brute --threads 1 --isa avx2 -o {out}")]),
    ("decision-scalar-hull", "b89f19c", "772ac01",
     [rays(6, "regr01", "--isa avx512 --size 1024x1024"), rays(6, "sphere4k", "--isa avx512 --size 1024x1024"),
      rays(6, "regr01", "--isa avx2 --size 1024x1024"), rays(6, "WusonOBJ", "--isa avx2 --size 1024x1024")]),
    ("decision-fused-sign", "f67d973", "f49928e",
     [cpu(4, "bench paper --models mod2 --no-baselines --no-scaling --threads 1 --isa avx512"),
      cpu(4, "hits --mesh {mod2} --rays {mod2.csv} --accel brute --threads 1 --isa avx512 -o {out}"),
      cpu(4, "visibility {vis} --origin 0,0,-3 --accel brute --threads 1 --isa avx512 -o {out}")]),
    ("decision-binning-lanes", "7183f36", "8f58963",
     [cpu(5, "bench rays {sphere1m} --threads 1 --builds 7 --size 16x16 --repeats 1")]),
)


class Remeasure:
    def __init__(self, args):
        self.new = os.path.abspath(os.path.join(args.build, "rayvec"))
        self.against_build = args.against_build
        self.inputs = targets.Targets(argparse.Namespace(build=args.build, work=args.work, rounds=0))
        self.work = self.inputs.work
        self.has_avx512 = self.inputs.has_avx512
        self.has_embree = self.inputs.has_embree("remeasure's `rays` commands")

    def mesh(self, name):
        if name in FILES:
            return FILES[name]
        if name in ("sphere4k", "sphere1m"):
            return self.inputs.sphere(name)
        if name == "mod2":  # with its rays, mod2.csv
            return self.inputs.make("mod2.obj", [sys.executable, f"{ROOT}/scripts/make_paper_scene.py", "mod2.obj",
                                                 "mod2.csv"])
        return self.inputs.make("sphere40k.obj", [sys.executable, f"{ROOT}/scripts/make_bumpy_sphere.py",
                                                  "sphere40k.obj", "--rings", "100", "--segments", "200"])

    def vis(self):
        verts, faces = os.path.join(self.work, "sphere40k_verts.csv"), os.path.join(self.work, "sphere40k_faces.csv")
        if not os.path.exists(faces):
            subprocess.run([sys.executable, f"{ROOT}/scripts/obj_to_visibility.py", self.mesh("sphere40k"), verts,
                            faces], check=True)
        return f"--verts {verts} --faces {faces}"

    def expand(self, args):
        words = []
        for w in args.split():
            if w == "{vis}":
                words += self.vis().split()
            elif w == "{out}":
                words.append(os.path.join(self.work, "remeasure_out.csv"))
            elif w == "{mod2.csv}":
                self.mesh("mod2")
                words.append(os.path.join(self.work, "mod2.csv"))
            elif w.startswith("{") and w.endswith("}"):
                words.append(self.mesh(w[1:-1]))
            else:
                words.append(w)
        return words

    def runnable(self, command):
        kind, _, _, options = command
        if "avx512" in options and not self.has_avx512:
            return "skipped: no AVX-512 on this CPU"
        if kind == "rays" and not self.has_embree:
            return "skipped: this build has no Embree rival (libembree-dev, then rebuild)"
        return None

    def build_all(self, decisions):
        """Builds every commit the chosen Decisions compare, before any is measured: on every CPU, even
        when this script runs pinned (`taskset -c 0`), where make's jobs would share one core and the
        builds take about three times as long. Returns {commit: binary}."""
        commits = []
        for _, commit, made, commands in decisions:
            if any(self.runnable(c) is None for c in commands):
                commits += [commit] if self.against_build else [commit, made]
        commits = list(dict.fromkeys(commits))
        binaries = {}
        for k, commit in enumerate(commits, 1):
            log(f"remeasure: building {commit} ({k} of {len(commits)}, every CPU)")
            binaries[commit] = subprocess.run([f"{ROOT}/scripts/build_at.sh", commit], capture_output=True,
                                              text=True, check=True, preexec_fn=targets.unpinned).stdout.strip()
        return binaries

    def measure(self, old, new, command):
        kind, rounds, mesh, options = command
        if kind == "rays":
            cmd = [sys.executable, f"{ROOT}/scripts/bench_rays_rounds.py", str(rounds), self.mesh(mesh), options,
                   f"old={old}", f"new={new}"]
            return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip()
        args = self.expand(options)
        times = {"old": [], "new": []}
        for r in range(rounds):
            for name, binary in ((("old", old), ("new", new)) if r % 2 == 0 else (("new", new), ("old", old))):
                times[name].append(targets.run([binary] + args)[2])
        rel = statistics.median(n / o for n, o in zip(times["new"], times["old"]))
        return (f"old {statistics.median(times['old']):.3f} s, new {statistics.median(times['new']):.3f} s CPU "
                f"(medians of {rounds}); new / old per round, median {rel:.3f}")

    def run(self, decisions):
        against = f"; new: {self.new}" if self.against_build else ""
        binaries = self.build_all(decisions)
        print(f"# Decisions re-measured on {platform_line()}{against}\n")
        for anchor, commit, made, commands in decisions:
            new = self.new if self.against_build else made
            print(f"## [{anchor}](docs/benchmarks.md#{anchor}): {commit} → {new}\n")
            old = binaries.get(commit)
            new = self.new if self.against_build else binaries.get(made)
            for command in commands:
                label = describe(command)
                why = self.runnable(command)
                if why:
                    print(f"- {label}: {why}")
                    continue
                log(f"remeasure: {anchor}: {label}")
                print(f"- {label}:\n\n```\n{self.measure(old, new, command)}\n```\n")
            print()


def platform_line():
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    return f"{cpu}, {os.cpu_count()} CPUs (scripts at {head})"


def describe(command):
    kind, rounds, mesh, options = command
    if kind == "rays":
        return f"`bench_rays_rounds.py {rounds} {mesh} \"{options}\"`"
    return f"`rayvec {options}`, {rounds} alternating rounds"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--work", default="/tmp/rayvec-targets")
    parser.add_argument("--only", nargs="+", default=[])
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--against-build", action="store_true")
    args = parser.parse_args()
    names = {d[0].removeprefix("decision-"): d for d in DECISIONS}
    unknown = [n for n in args.only if n not in names]
    if unknown:
        print(f"remeasure: no Decision {', '.join(unknown)}; --list names them", file=sys.stderr)
        sys.exit(2)
    chosen = [names[n] for n in args.only] if args.only else list(DECISIONS)
    if args.list:
        for anchor, commit, made, commands in chosen:
            print(f"{anchor} {commit} {made}")
            for command in commands:
                print(f"  {describe(command)}")
        return
    Remeasure(args).run(chosen)


if __name__ == "__main__":
    main()
