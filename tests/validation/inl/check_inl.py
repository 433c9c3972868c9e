#!/usr/bin/env python3
"""LIGGGHTS-INL's decks through liggghts-granbond with `inlCompatible on`
give LIGGGHTS-INL's answers, within INL's own spread.

Each case folder holds a deck as LIGGGHTS-INL runs it and, in `inl/`, the
table INL wrote for it and the one it wrote with the whole scene moved by
1e-13 of a sphere diameter (`<table>.perturbed`). The check adds
`inlCompatible on` to every `cohesion bond/nonlinear` line, runs the deck
and compares each column with INL's, relative to the column's range in
INL's table: at every row the difference must stay within SPREAD_FACTOR
times INL's own largest difference under the perturbation up to that row
(or FLOOR, where INL reproduces itself to the last digit), so a chaotic
run is held to INL's digits until INL's own answers part.

    check_inl.py --liggghts BIN --case NAME --workdir DIR
    check_inl.py --liggghts BIN --case NAME --workdir DIR --without-switch
        (the deck as written: prints how far the default law is from INL)
    check_inl.py --liggghts BIN --case NAME --workdir DIR --mpiexec MPIEXEC --ranks N
        (granbond on N ranks)
    check_inl.py --inl INL_BIN --case NAME --workdir DIR --make-reference
        (writes inl/<table> and inl/<table>.perturbed with INL's binary)
"""

import argparse
import gzip
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "support"))
from deck_runner import Failure, main as run_check  # noqa: E402

# case -> (deck, table INL writes, sphere diameter in the deck's units)
CASES = {
    "probe_compression": ("in.probe", "probe.txt", 2e-3),
    "chain_bending_um_2": ("in.chain_bending.lmp", "output.csv", 1.0),
    "tension_3_spheres": ("in.particle_test", "out.loading.csv", 4e-4),
    "spin_twist_bend": ("in.spin", "spin.txt", 2e-3),
    "cycle_stress_break": ("in.cycle", "cycle.txt", 2e-3),
    "wall_bond": ("in.wall", "wall.txt", 2e-3),
    # LIGGGHTS-INL's linear bond (`cohesion bond`), run as written
    "linear_chain_bending": ("in.chain_bending.lmp", "chain.txt", 1e-3),
    "linear_chain_plate": ("in.chain_test", "chain.txt", 0.05),
    "linear_cycle_break": ("in.cycle", "cycle.txt", 2e-3),
    "linear_wall_bond": ("in.wall", "wall.txt", 2e-3),
    "linear_dissipated_shares": ("in.dissipated", "dissipated.txt", 2e-3),
}
# Columns of INL's table that are not what their names say, per case, and
# why: INL's linear bond files for atom j `-(torque on j - elastic torque on
# j)`, with the elastic torque's moments of the wrong sign
# (cohesion_model_bond.h, dTorqueEl_j), so its columns hold twice the sum
# of the bond's elastic moments besides minus the damping torque on j,
# which is what granbond files (docs/models/bond-linear.md, "Energy").
NOT_COMPARABLE = {"linear_dissipated_shares": re.compile(r"^t[xyz]2$")}
# Columns that are not results of the model (wall-clock time).
SKIP = re.compile(r"cpu", re.I)
SPREAD_FACTOR = 3.0
FLOOR = 1e-9
TIMEOUT_S = 600


def with_switch(text):
    """Every `cohesion bond/nonlinear` command with `inlCompatible on` at its
    end (after any comment is cut off)."""
    out = []
    for line in text.splitlines():
        if "cohesion bond/nonlinear" in line and not line.lstrip().startswith("#"):
            line = line.split("#", 1)[0].rstrip() + " inlCompatible on"
        out.append(line)
    return "\n".join(out) + "\n"


def perturbed(text, shift):
    """The deck with every atom moved by `shift` along x, y and z before
    the first run."""
    out, done = [], False
    for line in text.splitlines():
        if not done and re.match(r"\s*run\s", line):
            out.append(f"displace_atoms all move {shift!r} {shift!r} {shift!r} units box")
            done = True
        out.append(line)
    if not done:
        raise Failure("the deck has no run command")
    return "\n".join(out) + "\n"


def run(binary, case, workdir, deck_text, launcher=()):
    deck, table, _ = CASES[case]
    if os.path.isdir(workdir):
        shutil.rmtree(workdir)
    shutil.copytree(os.path.join(HERE, case), workdir, ignore=shutil.ignore_patterns("inl"))
    os.makedirs(os.path.join(workdir, "post"), exist_ok=True)
    with open(os.path.join(workdir, deck), "w", encoding="utf-8") as f:
        f.write(deck_text)
    proc = subprocess.run(list(launcher) + [binary, "-in", deck], cwd=workdir, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=TIMEOUT_S, check=False)
    screen = proc.stdout.decode("utf-8", "replace")
    if proc.returncode != 0:
        raise Failure(f"{case}: {binary} exited with {proc.returncode}:\n{screen[-3000:]}")
    return os.path.join(workdir, table), screen


def read_table(path):
    """(column names, rows) of a `fix print` table, commas or blanks."""
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", encoding="utf-8") as f:
        lines = [line for line in f if line.strip()]
    sep = "," if "," in lines[0] else None
    names = [n.strip() for n in lines[0].lstrip("#").split(sep)]
    rows = [[float(v) for v in line.split(sep) if v.strip()] for line in lines[1:]]
    return names, rows


def reference(case, suffix=""):
    table = CASES[case][1]
    for name in (table + suffix, table + suffix + ".gz"):
        path = os.path.join(HERE, case, "inl", name)
        if os.path.exists(path):
            return path
    raise Failure(f"{case}: no INL table {table + suffix} in {os.path.join(HERE, case, 'inl')}")


def compare(case, table):
    """Per column: (largest difference / range, its row, INL's spread over
    the run / range, the rows outside the allowed band)."""
    names, inl = read_table(reference(case))
    _, spread_rows = read_table(reference(case, ".perturbed"))
    got_names, got = read_table(table)
    if got_names != names:
        raise Failure(f"{case}: columns {got_names} against INL's {names}")
    if len(got) != len(inl) or len(spread_rows) != len(inl):
        raise Failure(f"{case}: {len(got)} rows against INL's {len(inl)}")
    out = {}
    apart = NOT_COMPARABLE.get(case)
    for c, name in enumerate(names):
        if SKIP.search(name) or (apart and apart.search(name)):
            continue
        column = [row[c] for row in inl]
        span = max(column) - min(column)
        if span == 0.0:
            span = max(abs(v) for v in column) or 1.0
        running, worst, at, spread, outside = 0.0, 0.0, 0, 0.0, []
        for k, (mine, theirs, shifted) in enumerate(zip(got, inl, spread_rows)):
            running = max(running, abs(shifted[c] - theirs[c]) / span)
            d = abs(mine[c] - theirs[c]) / span
            if d > worst:
                worst, at = d, k
            if d > max(SPREAD_FACTOR * running, FLOOR):
                outside.append(k)
        out[name] = (worst, at, running, outside)
    return names, out


def check(args):
    deck, table, diameter = CASES[args.case]
    with open(os.path.join(HERE, args.case, deck), encoding="utf-8") as f:
        text = f.read()
    if args.make_reference:
        target = os.path.join(HERE, args.case, "inl")
        os.makedirs(target, exist_ok=True)
        for suffix, deck_text in (("", text), (".perturbed", perturbed(text, 1e-13 * diameter))):
            path, _ = run(args.inl, args.case, os.path.join(args.workdir, "inl" + suffix), deck_text)
            shutil.copy(path, os.path.join(target, table + suffix))
        print(f"wrote {target}")
        return
    deck_text = text if args.without_switch else with_switch(text)
    launcher = []
    if args.ranks > 1:
        launcher = [args.mpiexec, "-np", str(args.ranks), "--oversubscribe"]
        if os.geteuid() == 0:
            launcher.append("--allow-run-as-root")
    path, _ = run(args.liggghts, args.case, os.path.join(args.workdir, "granbond"), deck_text, launcher)
    names, diff = compare(args.case, path)
    failures = []
    print(f"{args.case}: largest difference over the run / range of the column in INL's table")
    print(f"{'column':>12} {'granbond':>10} {'INL spread':>10}  row  rows outside")
    for name in names:
        if name not in diff:
            continue
        worst, row, spread, outside = diff[name]
        print(f"{name:>12} {worst:10.3g} {spread:10.3g} {row:4d}  {len(outside)}")
        if outside:
            failures.append(f"{name}: {len(outside)} rows beyond {SPREAD_FACTOR} x INL's spread so far, "
                            f"the first {outside[0]}")
    if args.without_switch:
        print(f"without the switch: {len(failures)} of {len(diff)} columns outside INL's spread")
        return
    if failures:
        raise Failure(f"{args.case}: granbond differs from INL beyond its spread: "
                      + "; ".join(failures))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--liggghts")
    ap.add_argument("--inl")
    ap.add_argument("--without-switch", action="store_true")
    ap.add_argument("--make-reference", action="store_true")
    ap.add_argument("--mpiexec", help="to run granbond on --ranks ranks")
    ap.add_argument("--ranks", type=int, default=1)
    parsed = ap.parse_args()
    run_check(lambda: check(parsed))
