#!/usr/bin/env python3
"""scripts/remeasure.py against docs/benchmarks.md: every row of the table "Re-measuring a Decision"
(its first Decision link, its old commit and the commit that made the Decision) is a Decision the
script re-measures between those commits, the script has none the table lacks, each anchor exists in
the document, and an unknown --only name exits 2. Runs nothing but --list."""
import re
import subprocess
import sys

root = sys.argv[1]
doc = open(f"{root}/docs/benchmarks.md").read()
start = doc.index("| Decision | old | new | command |")
table = doc[start:doc.index("\n\n", start)]
rows = set(re.findall(r"^\| \[(decision-[\w-]+)\]\(#\1\)[^|]*\| ([0-9a-f]{7,40}) \| ([0-9a-f]{7,40}) \|", table, re.M))
assert len(rows) == table.count("\n") - 1, f"a table row not understood:\n{table}"
listed = subprocess.run([sys.executable, f"{root}/scripts/remeasure.py", "--list"], capture_output=True, text=True,
                        check=True).stdout
decisions = set(re.findall(r"^(decision-[\w-]+) ([0-9a-f]+) ([0-9a-f]+)$", listed, re.M))
commands = re.findall(r"^  `", listed, re.M)
failures = []
if rows != decisions:
    failures.append(f"table only: {sorted(rows - decisions)}; script only: {sorted(decisions - rows)}")
if len(commands) < len(decisions):
    failures.append("a Decision without a command")
for anchor, _, _ in decisions:
    if f'<a id="{anchor}"></a>' not in doc:
        failures.append(f"no anchor {anchor} in docs/benchmarks.md")
bad = subprocess.run([sys.executable, f"{root}/scripts/remeasure.py", "--only", "no-such-decision"],
                     capture_output=True, text=True)
if bad.returncode != 2 or "--list" not in bad.stderr:
    failures.append(f"--only no-such-decision exited {bad.returncode}: {bad.stderr!r}")
if failures:
    sys.exit("\n".join(failures))
print(f"remeasure.py: {len(decisions)} Decisions, as the table lists them")
