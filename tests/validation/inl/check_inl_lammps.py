#!/usr/bin/env python3
"""LAMMPS `pair granbond` gives LIGGGHTS-INL's answers for its code
(`inl_compatible yes`) and its linear bond (`bond/linear`), and the same
numbers as LIGGGHTS on the same scene with the same contact.

Each case is a deck of lammps/ written for the scene of an INL deck of
this folder:

- against INL's own table (`<case>/inl/`), with check_inl.py's tolerances
  (3 times INL's own spread so far at every row, at least 1e-9 of the
  column's range), at the rows where the spheres do not overlap, or at
  every row where the contact under the bond carries nothing (INL's contact
  is Hertz's, LAMMPS's the Voigt contact);
- against liggghts-granbond on INL's deck with the Voigt contact in place of
  INL's (the same stiffnesses), at every row, to 1e-9 of the column's
  range: the contact's loads under the overlapping bond are those the
  bond's law keeps (INL's code: the tangential and rolling ones; its linear
  bond: all of them), and the contact goes on under the bond in both
  engines where the decks do not say (`contact_under_bond` by the law) as
  with LIGGGHTS's `contactUnderBond on`; with `contactUnderBond off` the
  LIGGGHTS run differs (the scene shears the overlapping bond, so the
  contact's spring under it shows in the loads);
- the run's opening lines name the law the bonds follow (the core's line),
  which no WARNING repeats.

    check_inl_lammps.py --lammps LMP --liggghts LIGGGHTS --case NAME --workdir DIR
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "support"))
sys.path.insert(0, HERE)
from deck_runner import Failure, main as run_check  # noqa: E402
import check_inl  # noqa: E402

# The Voigt contact of the LAMMPS decks, as LIGGGHTS properties: for model
# voigt / tangential voigt / rolling_friction voigt (kn, kt, ...) and for
# model hooke/stiffness with absolute damping (k_n, k_t, ...).
VOIGT_PROPERTIES = """fix v1 all property/global kn peratomtypepair 1 1e6
fix v2 all property/global kt peratomtypepair 1 5e5
fix v3 all property/global gamman_abs peratomtypepair 1 1e-2
fix v4 all property/global gammat_abs peratomtypepair 1 1e-2
fix v5 all property/global rollingStiffness peratomtypepair 1 1e-4
fix v6 all property/global rollingDamping peratomtypepair 1 1e-7
fix v7 all property/global coefficientRollingFriction peratomtypepair 1 0.05
fix v8 all property/global rollingViscousDamping peratomtypepair 1 2e-8
fix v9 all property/global k_n peratomtypepair 1 1e6
fix v10 all property/global k_t peratomtypepair 1 5e5
"""

# case -> (LAMMPS deck, each LIGGGHTS run: its contact models, its
#          contactUnderBond words ("": as the law says) and whether it gives
#          LAMMPS's numbers, rows compared with INL's table: "apart" or
#          "all", the law's line)
CASES = {
    # INL's code: the Voigt normal model's load replaced by the bond, the
    # tangential and rolling ones kept, with the whole voigt contact in one
    # call, and with hooke/stiffness (absolute damping, no attraction: the
    # Voigt normal force) leaving the tangential and rolling voigt models
    # their own calls
    "cycle_stress_break": ("in.cycle_stress_break",
                           [("model voigt tangential voigt", "rolling_friction voigt", "",
                             "contactUnderBond on", True),
                            ("model voigt tangential voigt", "rolling_friction voigt", "", "", True),
                            ("model voigt tangential voigt", "rolling_friction voigt", "",
                             "contactUnderBond off", False),
                            ("model hooke/stiffness tangential voigt", "rolling_friction voigt",
                             "absolute_damping on limitForce on", "", True)],
                           "apart", "LIGGGHTS-INL's code (inl_compatible on)"),
    # INL's linear bond: every load of the Voigt contact kept, the bond's
    # added (model voigt tangential voigt: one core call for the contact)
    "linear_cycle_break": ("in.linear_cycle_break",
                           [("model voigt tangential voigt", "rolling_friction voigt", "",
                             "contactUnderBond on", True),
                            ("model voigt tangential voigt", "rolling_friction voigt", "", "", True)],
                           "apart", "LIGGGHTS-INL's linear bond"),
    # the spheres never overlap; sphere 2 free after the first run, from
    # the loads of the second run's setup pass (INL's trial step)
    "spin_twist_bend": ("in.spin_twist_bend", [], "all", "LIGGGHTS-INL's code (inl_compatible on)"),
    # head-on: the Voigt contact's normal load replaced, nothing tangential
    "probe_compression": ("in.probe_compression", [], "all", "LIGGGHTS-INL's code (inl_compatible on)"),
}
ENGINE_FLOOR = 1e-9
# a run that must not give LAMMPS's numbers differs by more than this
# somewhere (of a column's range)
DIFFERS_BY = 1e-3


def fresh(workdir):
    if os.path.isdir(workdir):
        shutil.rmtree(workdir)
    os.makedirs(workdir)
    return workdir


def run(command, deck_path, workdir, table):
    proc = subprocess.run(command + ["-in", deck_path], cwd=workdir, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=check_inl.TIMEOUT_S, check=False)
    screen = proc.stdout.decode("utf-8", "replace")
    if proc.returncode != 0:
        raise Failure(f"{' '.join(command)} -in {deck_path} exited with {proc.returncode}:\n{screen[-3000:]}")
    return os.path.join(workdir, table), screen


def without_setup_rows(deck_path, rows):
    """The rows of a LAMMPS `fix print` table less those it writes in each
    run's setup (LIGGGHTS writes none there): the deck's runs and print
    interval say where they are."""
    with open(deck_path, encoding="utf-8") as f:
        text = f.read()
    every = int(re.search(r"^fix \S+ all print (\d+)", text, re.M).group(1))
    kept, k = [], 0
    for n in (int(m) for m in re.findall(r"^run (\d+)", text, re.M)):
        kept += rows[k + 1:k + 1 + n // every]
        k += 1 + n // every
    if k != len(rows):
        raise Failure(f"{deck_path}: {len(rows)} rows, {k} expected from its runs")
    return kept


def liggghts_deck(case, models, under, workdir):
    """INL's deck of `case` with the Voigt contact of the LAMMPS deck in
    place of INL's, its bond as INL's (`inlCompatible on` for
    bond/nonlinear), `under` the deck's contactUnderBond words."""
    deck = check_inl.CASES[case][0]
    with open(os.path.join(HERE, case, deck), encoding="utf-8") as f:
        text = f.read()
    out = []
    for line in text.splitlines():
        if line.startswith("pair_style gran"):
            words = line.split("#", 1)[0].split()
            at = words.index("cohesion")
            # the engine's order: models, cohesion, rolling, then the settings
            front, rolling, settings = models
            line = " ".join(["pair_style gran", front] + words[at:at + 2] + [rolling, settings]
                            + words[at + 2:] + under.split())
            if "bond/nonlinear" in words:
                line += " inlCompatible on"
            out.append(VOIGT_PROPERTIES.rstrip("\n"))
        out.append(line)
    path = os.path.join(workdir, deck)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
    return path


def apart_rows(names, rows):
    """The rows at which the spheres of the scene do not overlap: the
    compression column `d` (2 R - r) is not positive."""
    if "d" not in names:
        raise Failure(f"no compression column d in {names}")
    c = names.index("d")
    return [k for k, row in enumerate(rows) if row[c] <= 0.0]


def lammps_table(deck_path, table):
    names, rows = check_inl.read_table(table)
    return names, without_setup_rows(deck_path, rows)


def against_inl(case, deck_path, table, which):
    names, inl = check_inl.read_table(check_inl.reference(case))
    _, spread_rows = check_inl.read_table(check_inl.reference(case, ".perturbed"))
    got_names, got = lammps_table(deck_path, table)
    if got_names != names or len(got) != len(inl):
        raise Failure(f"{case}: LAMMPS wrote {got_names} x {len(got)} rows, INL {names} x {len(inl)}")
    compared = apart_rows(names, inl) if which == "apart" else list(range(len(inl)))
    failures = []
    print(f"{case}: LAMMPS against INL's table at {len(compared)} of {len(inl)} rows "
          f"({'the spheres apart' if which == 'apart' else 'all'})")
    print(f"{'column':>8} {'largest':>10} {'INL spread':>10}  rows outside")
    for c, name in enumerate(names):
        if check_inl.SKIP.search(name):
            continue
        column = [row[c] for row in inl]
        span = (max(column) - min(column)) or (max(abs(v) for v in column) or 1.0)
        running, worst, outside = 0.0, 0.0, []
        for k in range(len(inl)):
            running = max(running, abs(spread_rows[k][c] - inl[k][c]) / span)
            if k not in compared:
                continue
            d = abs(got[k][c] - inl[k][c]) / span
            worst = max(worst, d)
            if d > max(check_inl.SPREAD_FACTOR * running, check_inl.FLOOR):
                outside.append(k)
        print(f"{name:>8} {worst:10.3g} {running:10.3g}  {len(outside)}")
        if outside:
            failures.append(f"{name}: {len(outside)} rows beyond INL's spread, the first {outside[0]} "
                            f"(LAMMPS {got[outside[0]][c]!r}, INL {inl[outside[0]][c]!r})")
    return failures


def against_liggghts(case, deck_path, mine, theirs, same=True):
    names, a = lammps_table(deck_path, mine)
    other, b = check_inl.read_table(theirs)
    if names != other or len(a) != len(b):
        raise Failure(f"{case}: LAMMPS wrote {names} x {len(a)} rows, LIGGGHTS {other} x {len(b)}")
    failures = []
    print(f"{case}: LAMMPS against LIGGGHTS, every row ({'the same' if same else 'not the same'} numbers)")
    largest = 0.0
    for c, name in enumerate(names):
        column = [row[c] for row in b]
        span = (max(column) - min(column)) or (max(abs(v) for v in column) or 1.0)
        diffs = [abs(x[c] - y[c]) / span for x, y in zip(a, b)]
        worst = max(diffs)
        largest = max(largest, worst)
        print(f"{name:>8} {worst:10.3g}")
        if same and worst > ENGINE_FLOOR:
            k = diffs.index(worst)
            failures.append(f"{name}: row {k} differs by {worst:.3g} of the range "
                            f"(LAMMPS {a[k][c]!r}, LIGGGHTS {b[k][c]!r})")
    if not same and largest <= DIFFERS_BY:
        failures.append(f"no column differs by more than {DIFFERS_BY:g} of its range (largest {largest:.3g})")
    return failures


def check(args):
    deck, models, which, law = CASES[args.case]
    table = check_inl.CASES[args.case][1]
    deck_path = os.path.join(HERE, "lammps", deck)
    mine, screen = run([os.path.abspath(args.lammps)], deck_path, fresh(os.path.join(args.workdir, "lammps")), table)
    failures = []
    said = [line for line in screen.splitlines() if line.startswith("pair granbond: ")]
    if not any(law in line for line in said):
        failures.append(f"the run's opening lines do not name the law ('{law}'): {said}")
    else:
        print(f"opening line: {[line for line in said if law in line][0]}")
    # the law is told, not warned (the decks' time steps are warned: INL's
    # prescribed motions step beyond the bonds' critical step)
    warned = [line for line in screen.splitlines() if line.startswith("WARNING") and "LIGGGHTS-INL" in line]
    if warned:
        failures.append(f"the law is warned on a correct deck: {warned}")
    failures += against_inl(args.case, deck_path, mine, which)
    for k, (*contact, under, same) in enumerate(models):
        workdir = fresh(os.path.join(args.workdir, f"liggghts_{k}"))
        path = liggghts_deck(args.case, contact, under, workdir)
        theirs, _ = run([os.path.abspath(args.liggghts)], path, workdir, table)
        said = under or "contactUnderBond not given"
        print(f"LIGGGHTS: {contact[0]} ... {contact[1]}, {said}")
        failures += [f"against {contact[0]}, {said}: {f}"
                     for f in against_liggghts(args.case, deck_path, mine, theirs, same)]
    if failures:
        raise Failure(f"{args.case}: " + "; ".join(failures))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--lammps", required=True)
    ap.add_argument("--liggghts", required=True)
    ap.add_argument("--workdir", required=True)
    parsed = ap.parse_args()
    run_check(lambda: check(parsed))
