#!/usr/bin/env python3
"""What a CPU model says the brute-force kernel's inner loop costs: a host of one vendor estimates
another's throughput (llvm-mca's port model) where it cannot run there.

    scripts/port_model.py [--isa avx512|avx2] [--rays 1|2|4|8|16] [--pretest ordered|sign]
                          [--origin shared|separate] [--normals stored|formed] [--cpu NAME ...]
                          [--max-cycles C] [OBJECT ...]

Disassembles the `closest_mt_float_rays` kernel for R rays (by default the group that rays from one
origin, as a camera's are, go through: 16, tested once a step by the crossed group test; a pair is
from one origin unless --origin separate) or, for --rays 1, `closest_mt_float_one`
(tmin = 0) of an ISA unit of a built tree, follows its
triangle loop — of the walk over stored normals, or with --normals formed the one forming them — along the path a step takes when no lane passes the pre-test (every early-out taken:
the path almost every step takes), and runs that straight-line body through `llvm-mca` for each
--cpu (default: icelake-server, the model closest to the Xeons' Golden Cove cores in LLVM 14, and
skylake-avx512). Prints cycles per loop iteration, the busiest ports and tests per cycle (16 or 8
tests per ray and iteration). A model, not a measurement: it ignores caches, frequency and the
front end; docs/benchmarks.md quotes it beside what the same loop measured. OBJECT: the ISA's kernel
unit's object file(s) (default: the one of build/); the first that defines the kernel is read.
--max-cycles C exits 1 when the first --cpu's cycles an iteration exceed C (the test that guards the
loop's length); exit 77 when llvm-mca is missing (Debian: llvm).
"""
import argparse
import re
import shutil
import subprocess
import sys
import tempfile

PRETEST = {"sign": 0, "ordered": 1}
# per ISA: its namespace as mangled, the lanes of a step
ISAS = {"avx512": ("6avx512", 16), "avx2": ("4avx2", 8)}


def default_object(isa):
    return f"build/src/CMakeFiles/rayvec_core_{isa}.dir/kernels/triangle_kernels_{isa}.cpp.o"


def symbol(isa, rays, pretest, shared, crossed):
    """closest_mt_float_rays<vfloat, true, R, P, shared, crossed> or closest_mt_float_one<vfloat, true, P>."""
    ns = ISAS[isa][0]
    if rays > 1:
        return (f"_ZN6rayvec{ns}21closest_mt_float_raysINS0_6vfloatELb1ELi{rays}ELNS_9MtPretestE"
                f"{PRETEST[pretest]}ELb{int(shared)}ELb{int(crossed)}EEEvRKNS_14TriangleArraysEjjPKNS_3RayEPNS_3HitEf")
    return (f"_ZN6rayvec{ns}20closest_mt_float_oneINS0_6vfloatELb1ELNS_9MtPretestE"
            f"{PRETEST[pretest]}EEEvRKNS_14TriangleArraysEjjRKNS_3RayERNS_3HitE")


def instructions(objects, sym):
    for obj in objects:
        run = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-M", "intel", f"--disassemble={sym}", obj],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"port_model: objdump cannot read {obj}: {run.stderr.strip()}")
        out = run.stdout
        code = disassembly(out)
        if code:
            return code
    sys.exit(f"port_model: {sym} not found in {' '.join(objects)} (build the tree first)")


def disassembly(out):
    code = []
    for line in out.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\t(.*)$", line)
        if m:
            text = re.sub(r"\s*(<[^>]*>|#.*)$", "", m.group(2)).strip()
            code.append((int(m.group(1), 16), text))
    return code


def loop_body(code, rays, tests, normals, least_products):
    """The loop's straight-line path with every branch after a mask test taken (no lane passed), in
    the walk that reads stored normals or the one that forms them (the kernel has both); `tests`:
    the mask tests a step has on that path at least. A step of a ray has 16 products and FMAs with
    stored normals (11 in the crossed group test): a loop with fewer than `least_products` a ray is
    not the triangle loop."""
    index = {addr: i for i, (addr, _) in enumerate(code)}
    # a step's early-out: a conditional branch on a mask register (AVX-512), on a vtestps, or on sign
    # bits a vmovmskps took in the three instructions before it (AVX2)
    def early_out(i):
        if not re.fullmatch(r"j(?!mp)\w+\s+[0-9a-f]+", code[i][1]) or i < 1:
            return False
        return code[i - 1][1].startswith(("kortest", "vtestp", "vptest")) or any(
            t.startswith("vmovmsk") for _, t in code[max(0, i - 3):i])

    exits = {i for i in range(len(code)) if early_out(i)}

    # a group's test branches (through unconditional jumps) to the out-of-line call of its rays'
    # steps where a lane passed, and falls through where none did
    def to_call(target):
        i, hops = index.get(target, len(code)), 0
        for _ in range(80):
            if i >= len(code):
                return False
            text = code[i][1]
            if text.startswith("call"):
                return True
            if re.fullmatch(r"jmp\s+[0-9a-f]+", text) and hops < 3:
                i, hops = index.get(int(text.split()[1], 16), len(code)), hops + 1
                continue
            if text.startswith("j"):
                return False
            i += 1
        return False

    def mask_tests(tail, head):
        return sum(1 for i in exits if head <= code[i][0] <= tail)

    def path(tail, head):
        body, i = [], index[head]
        for _ in range(10000):
            if i >= len(code):
                return None
            addr, text = code[i]
            if text.startswith("j"):
                target = int(text.split()[1], 16) if re.fullmatch(r"j\w+\s+[0-9a-f]+", text) else None
                if addr == tail:
                    return body
                if i in exits and target is not None and not to_call(target):  # no lane passed: skip ahead
                    i = index.get(target, len(code))
                    continue
            elif not text.startswith("nop"):
                body.append(text)
            i += 1
        return None

    # the triangle loops: conditional backward branches around a step's mask tests (pre-test and
    # exact test of each ray, or the one pre-test of a group) whose no-hit path closes; of each
    # walk's, the shortest
    loops = [(addr, int(t.split()[1], 16)) for addr, t in code
             if re.fullmatch(r"j(?!mp)\w+\s+[0-9a-f]+", t) and int(t.split()[1], 16) < addr]

    def products(b):
        return sum(1 for t in b if t.startswith(("vmulps", "vfmadd", "vfmsub", "vfnmadd", "vfnmsub")))

    bodies = [b for b in (path(*span) for span in loops if mask_tests(*span) >= tests)
              if b and products(b) >= least_products * rays]
    if not bodies:
        sys.exit("port_model: no loop found")
    # the walk loading the normal has the fewest products a step; the one forming it, its cross
    # product more (the shortest such loop: longer ones are copies the compiler unrolled)
    fewest = min(products(b) for b in bodies)
    chosen = [b for b in bodies if (products(b) == fewest) == (normals == "stored")]
    if not chosen:
        sys.exit(f"port_model: no loop with {normals} normals found")
    return min(chosen, key=len)


def model(body, cpu):
    with tempfile.NamedTemporaryFile("w", suffix=".s") as f:
        f.write(".intel_syntax noprefix\n" + "\n".join(body) + "\n")
        f.flush()
        out = subprocess.run(["llvm-mca", f"-mcpu={cpu}", "-iterations=1000", "-resource-pressure", f.name],
                             check=True, capture_output=True, text=True).stdout
    cycles = int(re.search(r"Total Cycles:\s+(\d+)", out).group(1)) / 1000
    lines = out.splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("Resource pressure per iteration"))
    names = re.findall(r"\[(\d+)\]", lines[k + 1])
    values = [0.0 if v == "-" else float(v) for v in lines[k + 2].split()]
    resources = dict(re.findall(r"\[(\d+)\]\s+-\s+(\S+)", out))
    busiest = sorted(zip(values, names), reverse=True)[:3]
    return cycles, ", ".join(f"{resources.get(n, n)} {v:.1f}" for v, n in busiest)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0].replace("\n", " "),
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("objects", nargs="*", metavar="OBJECT")
    p.add_argument("--isa", choices=sorted(ISAS), default="avx512", help="the kernel unit (default avx512)")
    p.add_argument("--rays", type=int, choices=(1, 2, 4, 8, 16),
                   help="rays per triangle load (default: the one-origin group, 16)")
    p.add_argument("--pretest", choices=sorted(PRETEST),
                   help="the pre-test form (default: what Intel runs, ordered on AVX-512, sign on AVX2)")
    p.add_argument("--origin", choices=("shared", "separate"), default="shared",
                   help="--rays 2: the kernel for rays from one origin (default) or from two")
    p.add_argument("--normals", choices=("stored", "formed"), default="stored",
                   help="the walk over stored normals (brute force, small BVHs; default) or formed ones")
    p.add_argument("--cpu", action="append", help="llvm-mca -mcpu (repeatable)")
    p.add_argument("--max-cycles", type=float, help="exit 1 when the first model's cycles exceed this")
    a = p.parse_args()
    a.pretest = a.pretest or ("ordered" if a.isa == "avx512" else "sign")
    a.rays = a.rays or 16
    if not shutil.which("llvm-mca"):
        print("port_model: llvm-mca not found (Debian: apt install llvm)", file=sys.stderr)
        sys.exit(77)
    shared = a.rays > 2 or a.origin == "shared"
    # four rays and more from one origin test the step once for all of them (the crossed group test,
    # mt_any_ray_passes_crossed: the mesh and rays of a benchmark never need the per-ray one), as a
    # pair from one origin does with the sign bits, and leave the rays' own tests to an out-of-line
    # call; else two mask tests a ray
    crossed = shared and a.rays >= 4
    sym = symbol(a.isa, a.rays, a.pretest, shared, crossed)
    mask_tests = 1 if crossed or (shared and a.rays > 1 and a.pretest == "sign") else 2 * a.rays
    body = loop_body(instructions(a.objects or [default_object(a.isa)], sym), a.rays, mask_tests, a.normals,
                     10 if crossed else 12)
    tests = ISAS[a.isa][1] * a.rays
    print(f"loop: {len(body)} instructions, {tests} ray-triangle tests an iteration "
          f"({a.isa}, {a.rays} ray(s){', ' + a.origin + ' origin' if a.rays == 2 else ''}, {a.pretest} pre-test, "
          f"{a.normals} normals)")
    first = None
    for cpu in a.cpu or ["icelake-server", "skylake-avx512"]:
        cycles, busiest = model(body, cpu)
        first = cycles if first is None else first
        print(f"{cpu}: {cycles:.1f} cycles an iteration, {tests / cycles:.2f} tests/cycle; busiest: {busiest}")
    if a.max_cycles is not None and first > a.max_cycles:
        print(f"port_model: {first:.1f} cycles an iteration, more than the {a.max_cycles:g} allowed: the loop "
              "got longer on Intel's ports (docs/benchmarks.md#decision-fewer-step-instructions)", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
