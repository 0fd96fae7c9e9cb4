#!/usr/bin/env python3
"""Measures the whole-product targets of docs/benchmarks.md ("Targets") on this machine in one
command and prints them as Markdown: one row per target (asked, measured, met), then the numbers
behind each row. It makes its inputs in --work the first time (a few minutes) and reuses them.

    scripts/targets.py [--build DIR] [--work DIR] [--rounds N] [--skip SECTION ...]

Sections (each can be skipped; one whose tool is missing is skipped with the reason printed):
  startup  scripts/startup_cost.sh: --help, info and the 16x16 render (wall, CPU, RSS)
  brute    `hits --accel brute --threads 1` against hits_reference (whole process, CPU time,
           alternating rounds), its tracing time against `bench paper` vec-mt on the same work,
           and on AVX-512 the mt pre-tests against each other (`bench paper --pretest`)
  obj      `bench obj` on the 1M-triangle sphere: rayvec's reader on one thread (the process on every
           CPU, so that its two-thread column has two cores)
  embree   `bench rays --vs-embree` (one thread, alternating rounds, median ratio per set) on
           sphere4k, WusonOBJ (Debian's assimp-testmodels) and the 1M sphere at AVX2 and AVX-512,
           the 1M sphere also with its normals stored (`--stored-normals 1`) against the default;
           bytes per triangle of each tree; assimp's regr01 (long triangles) measured alongside,
           reported apart from the targets' meshes
  choices  the defaults that depend on the CPU's vendor or the mesh's size (`rayvec info` prints
           their rules), each option against its alternative on meshes either side of its line, per
           ISA (`bench rays --vs-embree`, 512x512, ratio of the ratios to Embree per round): node
           width, leaf call, packet slot cull, and one leaf step against two above 32,768 triangles
           (tracing only; the build's cost is in the Decision) — the measurements their Decisions
           rest on, on this CPU
  povray   every scenes/*.json and the 1M sphere's scene, `rayvec render --spp 1 --threads 1`
           against POV-Ray 3.7 on the converted scene (scripts/scene_to_pov.py), CPU time of the
           whole processes, alternating rounds; RMSE of the two pictures

CPU times are user + system time of the whole process (wait4). A fuzzer or build on another core
moves them little; run nothing on the measured core. A full run takes about 10 minutes at 4 rounds.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ASSIMP = "/usr/share/assimp/models/OBJ"
SETS = ("primary", "primary_packet", "shadow", "shadow_packet", "incoherent")
SET_NAMES = "primary / packets / shadow / shadow packets / incoherent"
SECTIONS = ("startup", "brute", "obj", "embree", "choices", "povray")


def log(message):
    print(message, file=sys.stderr, flush=True)


def unpinned():
    """In a child before exec: every CPU of the machine, whatever this script was pinned to
    (`taskset -c 0`), for work that is not measured on the pinned core or is meant to use them all."""
    try:
        os.sched_setaffinity(0, range(os.cpu_count() or 1))
    except OSError:  # a CPU outside this container's set: keep the inherited one
        pass


def run(cmd, cwd=None, every_cpu=False):
    """Runs cmd (on every CPU with every_cpu, else on this script's); returns (stdout, stderr, CPU
    seconds of the process). Its peak RSS: peak_rss_mb."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, cwd=cwd, preexec_fn=unpinned if every_cpu else None)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read().decode(), err.read().decode()
    if proc.returncode != 0:
        sys.exit(f"targets: {' '.join(map(str, cmd))} exited with {proc.returncode}:\n{stderr[-2000:]}")
    return stdout, stderr, usage.ru_utime + usage.ru_stime


def peak_rss_mb(cmd):
    """cmd's peak RSS in MB, read by GNU time; None where /usr/bin/time is missing. Not wait4's
    ru_maxrss: Python starts its children by vfork, and the kernel counts the parent's pages, the
    resident set of this script, into the child's peak."""
    if not os.path.exists("/usr/bin/time"):
        return None
    with tempfile.NamedTemporaryFile(mode="r") as kb:
        run(["/usr/bin/time", "-f", "%M", "-o", kb.name] + cmd)
        return int(kb.read().split()[-1]) / 1024


def to_embree(run, ray_set):
    """rayvec's rays per second over Embree's in one `bench rays --vs-embree --json` run."""
    return run[ray_set]["mrays_per_s"] / run["embree"][ray_set]["mrays_per_s"]


def median(values):
    return statistics.median(values)


def span(values, fmt="{:.2f}"):
    lo, hi = min(values), max(values)
    return fmt.format(lo) if fmt.format(lo) == fmt.format(hi) else f"{fmt.format(lo)}–{fmt.format(hi)}"


class Targets:
    def __init__(self, args):
        self.bin = os.path.abspath(os.path.join(args.build, "rayvec"))
        self.work = os.path.abspath(args.work)
        self.rounds = args.rounds
        self.rows = []     # (target, asked, measured, met)
        self.details = []  # lines under the table
        os.makedirs(self.work, exist_ok=True)
        self.info = run([self.bin, "info"])[0]
        self.has_avx512 = "avx512f=1 avx512dq=1" in self.info and "zmm=1" in self.info

    def row(self, target, asked, measured, met):
        self.rows.append((target, asked, measured, "met" if met else "**not met**"))

    def path(self, name):
        return os.path.join(self.work, name)

    def make(self, name, cmd):
        """Makes work file `name` with cmd unless it is there already."""
        if not os.path.exists(self.path(name)):
            log(f"targets: making {name}")
            run(cmd, cwd=self.work)
        return self.path(name)

    def sphere1m(self):
        self.make("sphere1m.json", [sys.executable, f"{ROOT}/scripts/make_bumpy_sphere.py", "sphere1m.obj",
                                   "--scene", "sphere1m.json"])
        return self.path("sphere1m.obj")

    # --- startup ---------------------------------------------------------------------------------
    def startup(self):
        out = run([f"{ROOT}/scripts/startup_cost.sh", "20", self.bin])[0]
        self.details.append("Start-up (`scripts/startup_cost.sh 20`):\n\n```\n" + out.strip() + "\n```")
        lines = re.findall(r"^(rayvec .*?)\s+([\d.]+) ms wall\s+(\S+) ms CPU\s+([\d.]+) MB RSS", out, re.M)
        helps = [(float(w), c, float(m)) for label, w, c, m in lines if "render" not in label]
        render = [(float(w), c, float(m)) for label, w, c, m in lines if "render" in label]
        cpu = [float(c) for _, c, _ in helps if c != "-"]
        wall, rss = max(w for w, _, _ in helps), max(m for _, _, m in helps)
        cpu_text = f", CPU {span(cpu, '{:.1f}')} ms" if cpu else ""
        self.row("start-up: `--help`, `info`, … before input", "≤ 15 ms, ≤ 20 MB",
                 f"wall ≤ {wall:.1f} ms{cpu_text}, RSS ≤ {rss:.1f} MB", wall <= 15 and rss <= 20)
        w, c, m = render[0]
        self.row("start-up: 16×16 one-cube render to PNG, whole process", "≤ 50 ms",
                 f"wall {w:.1f} ms, CPU {c} ms, RSS {m:.1f} MB", w <= 50)

    # --- brute -----------------------------------------------------------------------------------
    def brute(self):
        mesh = self.make("mod2.obj", [sys.executable, f"{ROOT}/scripts/make_paper_scene.py", "mod2.obj", "mod2.csv"])
        rays = self.path("mod2.csv")
        reference = None
        if self.has_avx512:
            reference = self.make("hits_reference", ["g++", "-O3", "-std=c++20", "-mavx512f", "-mavx512dq", "-mfma",
                                                     f"{ROOT}/scripts/hits_reference/hits_reference.cpp", "-o",
                                                     "hits_reference"])
        else:
            log("targets: no hits_reference: it needs AVX-512 (F, DQ), which this CPU lacks")
        ratios, ref_cpu, hits_cpu, traces = [], [], [], []
        for r in range(self.rounds):
            log(f"targets: hits --accel brute, round {r + 1} of {self.rounds}")
            if reference:
                ref_cpu.append(run([reference, mesh, rays])[2])
            _, err, b = run([self.bin, "hits", "--mesh", mesh, "--rays", rays, "--accel", "brute",
                                "--threads", "1", "-o", self.path("hits.csv")])
            hits_cpu.append(b)
            traces.append(float(re.search(r"\(([\d.]+) s cpu\)", err).group(1)))
        if reference:
            ratios = [a / b for a, b in zip(ref_cpu, hits_cpu)]
            self.row("`hits --accel brute --threads 1` against `hits_reference`, whole process", "≥ 2×",
                     f"{span(ratios)}× per round, median {median(ratios):.2f}×", median(ratios) >= 2)
            self.details.append(f"hits: `hits_reference` {span(ref_cpu)} s CPU, `hits --accel brute` "
                                f"{span(hits_cpu)} s (tracing {span(traces, '{:.3f}')} s), {self.rounds} rounds.")
        paper = [self.bench_paper("auto") for _ in range(3)]
        vec_mt = median([p["seconds"]["vectorized_mt"] for p in paper])
        gap = median(traces) / vec_mt - 1
        self.row("`hits` trace rate against `bench paper` vec-mt, same work", "within 10 %",
                 f"{gap * 100:+.0f} % ({median(traces):.3f} s against {vec_mt:.3f} s)", abs(gap) <= 0.10)
        tpc = {"sign": [], "ordered": []}
        for _ in range(self.rounds):
            for pretest in tpc:
                tpc[pretest].append(self.bench_paper(pretest)["tests_per_cycle"]["vectorized_mt"])
        auto = paper[0]
        self.details.append(f"`bench paper --models mod2`: vec-mt {auto['tests_per_cycle']['vectorized_mt']:.2f} tests "
                            f"per cycle at {auto['clock_ghz']['vectorized_mt']:.2f} GHz (pre-test {auto['pre']}, "
                            f"FMA/c {auto['fma_per_cycle']['vectorized_mt']:.2f}); `--pretest sign` "
                            f"{span(tpc['sign'])}, `--pretest ordered` {span(tpc['ordered'])} tests per cycle "
                            f"({self.rounds} alternating runs; docs/benchmarks.md#decision-sign-pretest).")

    def bench_paper(self, pretest):
        out = run([self.bin, "bench", "paper", "--models", "mod2", "--no-baselines", "--no-scaling",
                   "--json", "--pretest", pretest])[0]
        d = json.loads(out)
        row = d["table1"][0]
        row["pre"] = d["mt_pretest"]
        return row

    # --- obj -------------------------------------------------------------------------------------
    def obj(self):
        # on every CPU: fast-2 reads on two threads (pinned, both would share one core); the target
        # row is fast-1's, one thread either way
        out = run([self.bin, "bench", "obj", self.sphere1m(), "--repeats", "5"], every_cpu=True)[0]
        fast = re.search(r"^fast-1\s+(?:\S+\s+){3}\S+\s+(\S+)\s+(\S+)\s+(\S+)", out, re.M)
        seconds, mbs, reader = float(fast.group(1)), float(fast.group(2)), fast.group(3)
        self.row("OBJ loading, one thread (1M-triangle sphere, 39 MB)", "≥ 200 MB/s, ≤ 0.25 s",
                 f"{mbs:.0f} MB/s, {seconds:.3f} s ({reader} reader)", mbs >= 200 and seconds <= 0.25)
        self.details.append("`bench obj sphere1m.obj --repeats 5` (on every CPU):\n\n```\n" + out.strip() + "\n```")

    # --- embree ----------------------------------------------------------------------------------
    def has_embree(self, section):
        """Whether this build has the Embree rival; else says that `section` is skipped."""
        probe = subprocess.run([self.bin, "bench", "rays", f"{ROOT}/scenes/models/cube.obj", "--vs-embree",
                                "--size", "4x4", "--builds", "1", "--repeats", "1"], capture_output=True)
        if probe.returncode != 0:
            log(f"targets: {section} skipped: this build has no Embree rival (libembree-dev, then rebuild)")
        return probe.returncode == 0

    def sphere(self, name):
        """A bumpy sphere of the work folder: sphere4k, sphere250k or sphere1m."""
        if name == "sphere1m":
            return self.sphere1m()
        rings = {"sphere4k": ("32", "64"), "sphere250k": ("354", "354")}[name]
        return self.make(f"{name}.obj", [sys.executable, f"{ROOT}/scripts/make_bumpy_sphere.py", f"{name}.obj",
                                         "--rings", rings[0], "--segments", rings[1]])

    def embree(self):
        if not self.has_embree("embree"):
            return
        meshes = [self.sphere("sphere4k")]
        if os.path.exists(f"{ASSIMP}/WusonOBJ.obj"):
            meshes.append(f"{ASSIMP}/WusonOBJ.obj")
        meshes.append(self.sphere1m())
        # long triangles (spatial splits): measured alongside, not part of the target's meshes
        regr = f"{ASSIMP}/regr01.obj"
        extra = [regr] if os.path.exists(regr) else []
        isas = ["avx2"] + (["avx512"] if self.has_avx512 else [])
        runs = {}
        for r in range(self.rounds):
            for isa in isas:
                for mesh in meshes + extra:
                    log(f"targets: bench rays {os.path.basename(mesh)} --isa {isa}, round {r + 1} of {self.rounds}")
                    out = run([self.bin, "bench", "rays", mesh, "--vs-embree", "--json", "--threads", "1",
                               "--builds", "1", "--repeats", "3", "--isa", isa])[0]
                    runs.setdefault((isa, mesh), []).append(json.loads(out))
                # the 1M sphere's normals the other way (stored), the open vendor question of
                # docs/benchmarks.md#decision-normal-budget
                log(f"targets: bench rays {os.path.basename(meshes[-1])} --isa {isa} --stored-normals 1, "
                    f"round {r + 1} of {self.rounds}")
                out = run([self.bin, "bench", "rays", meshes[-1], "--vs-embree", "--json", "--threads", "1",
                           "--builds", "1", "--repeats", "3", "--isa", isa, "--stored-normals", "1"])[0]
                runs.setdefault((isa, "stored"), []).append(json.loads(out))
        byte_counts = []
        for isa in isas:
            worst, cells = None, []
            for mesh in meshes + extra:
                name = os.path.basename(mesh).removesuffix(".obj")
                med = {s: median([to_embree(d, s) for d in runs[(isa, mesh)]]) for s in SETS}
                byte_counts.append((f"{name} ({isa})", runs[(isa, mesh)][0]["bytes_per_tri"]))
                label = f"not a target, long triangles: {name}" if mesh in extra else name
                cells.append(f"{label} " + " / ".join(f"{med[s]:.2f}" for s in SETS))
                if mesh in extra:
                    continue
                low = min(med.values())
                worst = low if worst is None else min(worst, low)
                if isa == "avx512" and mesh == meshes[-1]:
                    inc = med["incoherent"]
                    self.row("AVX-512 1M sphere, incoherent rays, against Embree", "≥ 1.10×", f"{inc:.2f}×", inc >= 1.10)
            label = "AVX2 against Embree at `max_isa=avx2`" if isa == "avx2" else "AVX-512 against Embree"
            self.row(f"{label}, every set", "≥ 1.0×", f"lowest {worst:.2f}×", worst >= 1.0)
            self.details.append(f"`bench rays --vs-embree --threads 1 --isa {isa}`, median ratio of {self.rounds} "
                                f"alternating rounds, {SET_NAMES}: " + "; ".join(cells) + ".")
            default, stored = runs[(isa, meshes[-1])], runs[(isa, "stored")]
            rel = {k: median([to_embree(b, k) / to_embree(a, k) for a, b in zip(default, stored)]) for k in SETS}
            self.details.append(
                f"1M sphere, `--isa {isa}`: `--stored-normals 1` relative to the default (normals "
                f"{'stored' if default[0].get('stored_normals') else 'formed per step'}), median of the per-round "
                f"ratios, {SET_NAMES}: " + " / ".join(f"{rel[k]:.3f}" for k in SETS) +
                " (docs/benchmarks.md#decision-normal-budget).")
        worst = max(b for _, b in byte_counts)
        self.row("BVH + triangle rows, bytes per triangle", "≤ 64",
                 ", ".join(f"{n} {b:.1f}" for n, b in byte_counts), worst <= 64)

    # --- choices ---------------------------------------------------------------------------------
    # (option, its two values, the JSON key that reports it, meshes, Decision): each default is measured
    # against its alternative on a mesh on each side of its line (32,768 triangles for the node width
    # and the leaf call, 2^18 for the slot cull; Intel's AVX-512 takes 16-wide nodes at every size).
    CHOICES = (("--bvh-width", ("8", "16"), "bvh_width", ("sphere4k", "sphere1m"), "decision-node-width"),
               ("--direct-leaf", ("1", "2"), "leaf_call", ("sphere4k", "sphere1m"), "decision-inlined-leaf"),
               ("--slot-cull", ("0", "1"), "packet_slot_cull", ("sphere250k", "sphere1m"),
                "decision-packet-slot-cull"),
               ("--leaf-steps", ("2", "1"), "leaf_steps", ("sphere250k", "sphere1m"), "decision-leaf-size"))

    def choices(self):
        if not self.has_embree("choices"):
            return
        isas = ["avx2"] + (["avx512"] if self.has_avx512 else [])
        bench = [self.bin, "bench", "rays", "--vs-embree", "--json", "--threads", "1", "--builds", "1",
                 "--repeats", "3", "--size", "512x512"]
        for option, values, key, names, anchor in self.CHOICES:
            cells = []
            for isa in isas:
                for name in names:
                    mesh = self.sphere(name)
                    default = json.loads(run([self.bin, "bench", "rays", mesh, "--json", "--builds", "1",
                                              "--repeats", "1", "--size", "16x16", "--isa", isa])[0])[key]
                    runs = {v: [] for v in values}
                    for r in range(self.rounds):
                        log(f"targets: {option} {'|'.join(values)} on {name} --isa {isa}, round {r + 1} of "
                            f"{self.rounds}")
                        for v in (values if r % 2 == 0 else values[::-1]):
                            runs[v].append(json.loads(run(bench[:3] + [mesh] + bench[3:] + ["--isa", isa,
                                                                                            option, v])[0]))
                    a, b = runs[values[0]], runs[values[1]]
                    rel = [median([to_embree(y, k) / to_embree(x, k) for x, y in zip(a, b)]) for k in SETS]
                    cells.append(f"{isa} {name} (default {json.dumps(default)}) " +
                                 " / ".join(f"{x:.3f}" for x in rel))
            self.details.append(f"`bench rays --vs-embree --size 512x512 {option} {values[1]}` relative to "
                                f"`{option} {values[0]}`, median of {self.rounds} alternating rounds, {SET_NAMES}: "
                                + "; ".join(cells) + f" (docs/benchmarks.md#{anchor}).")

    # --- povray ----------------------------------------------------------------------------------
    def povray(self):
        if not shutil.which("povray"):
            log("targets: povray skipped: POV-Ray 3.7 is not installed (apt install povray)")
            return
        self.sphere1m()
        scenes = sorted(f"{ROOT}/scenes/{s}" for s in os.listdir(f"{ROOT}/scenes") if s.endswith(".json"))
        scenes.append(self.path("sphere1m.json"))
        cells, worst = [], None
        for scene in scenes:
            name = os.path.basename(scene).removesuffix(".json")
            camera = json.load(open(scene))["camera"]
            pov = self.path(f"{name}.pov")
            run([sys.executable, f"{ROOT}/scripts/scene_to_pov.py", scene, pov])
            rv_png, pov_png = self.path(f"{name}_rayvec.png"), self.path(f"{name}_pov.png")
            ours, theirs = [], []
            render = [self.bin, "render", scene, "--spp", "1", "--threads", "1", "-q", "-o", rv_png]
            for r in range(self.rounds):
                log(f"targets: {name} against POV-Ray, round {r + 1} of {self.rounds}")
                ours.append(run(render)[2])
                theirs.append(run(["povray", f"+I{pov}", f"+O{pov_png}", f"+W{camera['width']}",
                                   f"+H{camera['height']}", "-A", "+WT1", "-D", "File_Gamma=sRGB"])[2])
            ratio = median(theirs) / median(ours)
            worst = ratio if worst is None else min(worst, ratio)
            rmse = re.search(r"^rmse: (\S+)", run([self.bin, "compare", rv_png, pov_png])[0], re.M).group(1)
            rss = peak_rss_mb(render)
            rss_text = f"rayvec {rss:.0f} MB" if rss is not None else "rayvec's RSS not read: apt install time"
            cells.append(f"{name} {median(ours) * 1000:.0f} / {median(theirs) * 1000:.0f} ms ({ratio:.1f}×, "
                         f"RMSE {float(rmse):.3f}, {rss_text})")
        self.row("whole process against POV-Ray 3.7, one thread, every scene and the 1M sphere", "≥ 5×",
                 f"lowest {worst:.1f}×", worst >= 5)
        self.details.append(f"Whole process, rayvec / POV-Ray CPU, medians of {self.rounds} alternating runs: "
                            + "; ".join(cells) + ".")

    def report(self):
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True).stdout.strip() or "?"
        cpu = re.search(r"^cpu: (.*)$", self.info, re.M).group(1)
        isa = re.search(r"^isa: (.*)$", self.info, re.M).group(1)
        print(f"# Targets on {cpu}, isa {isa}, {os.cpu_count()} CPUs, {datetime.date.today()}, commit {commit}\n")
        print("| target | asked | measured | |\n|---|---|---|---|")
        for row in self.rows:
            print("| " + " | ".join(row) + " |")
        for line in self.details:
            print("\n" + line)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding rayvec")
    ap.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "rayvec-targets"),
                    help="folder for the inputs it makes and the outputs (default: TMPDIR/rayvec-targets)")
    ap.add_argument("--rounds", type=int, default=4, help="alternating rounds per comparison (default 4)")
    ap.add_argument("--skip", nargs="*", default=[], choices=SECTIONS, help="sections not to measure")
    args = ap.parse_args()
    if args.rounds < 1:
        ap.error("--rounds must be at least 1")
    targets = Targets(args)
    for section in SECTIONS:
        if section not in args.skip:
            getattr(targets, section)()
    targets.report()


if __name__ == "__main__":
    main()
