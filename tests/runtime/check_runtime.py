"""Engine-level checks of what a run does between and around runs
(docs/runtime-checks.md), for LAMMPS (lmp-granbond) and LIGGGHTS
(liggghts-granbond). One claim per mode:

  continuity  free motion (fix nve/sphere) continued by a second `run` or
              by write_restart + read_restart ends, at step 2N, in the state
              of the uninterrupted run: bit for bit (17 digits of every
              position, velocity, spin, force and torque) for a contact
              (--scene pair, a voigt pair sliding and rolling; both
              engines) for run N + run N on 1 and 2 ranks and restarts
              1 -> 1, 2 -> 1 and 2 -> 2. Bonds (--scene cluster, LAMMPS: 8
              bonded spheres, bond damping on) to 1e-7 relative: a run's
              setup pass evaluates the bonds' loads from their state, with
              the damping of the velocities the run starts with (keeping
              the last pass's loads would cost 72 bytes a bond), and on 2
              ranks the loads on ghost atoms reach their atoms in another
              order.

  timestep    the core's time-step check, in both engines: above the
              recommended step a run warns (EXCEEDS above the critical
              step), for a bond (LAMMPS; LIGGGHTS bonds: check_bond_book.py)
              and for a contact (both), at every `run`, and again in a run
              whose atom count changes to a new, shorter limit (LIGGGHTS
              insertion); at a safe step nothing is said.
  timestep-kt the LIGGGHTS time-step check of model voigt followed by the
              stock `tangential history` counts the tangential spring that
              model hands it, the deck's kt: with kt 1e6 N/m (critical step
              2.4e-6 s) a step of 5e-6 s EXCEEDS the critical step at every
              run, with kt 1e2 N/m (the normal spring limits: recommended
              step 9.2e-6 s) a step of 8e-6 s is not warned until the
              inserted spheres bring a shorter limit.
  creation    the bond's creation and break rules checked against each
              other at a run's start, in both engines: createDistance >
              maxDistance (bonds created and broken, every step under
              createBondAlways), createDistance below contact, a creation
              step that has passed, maxDistance below contact; each a
              warning naming the parameters as the engine's deck spells
              them, said once over two runs; consistent rules say nothing.
  renumber    `delete_atoms ... compress yes` (which renumbers the atom IDs
              the engines key each pair's history by) while bonds exist:
              the next run ends with an error naming `compress no` (both);
              with `compress no` the run goes on and the atom that
              never bonded feels no force from the deleted atom's bond.
  lost        bonds that vanish with their atoms (an atom deleted between
              runs, atoms lost through a fixed boundary): LIGGGHTS counts
              them as lost in compute bond/counter (column 7), so that
              created = broken + intact + lost at every output, with one
              warning naming the number; LAMMPS warns each loss with its
              number; 1 and 2 ranks.

usage: check_runtime.py --mode MODE --engine BIN --kind lammps|liggghts
                        [--scene S] [--mpiexec MPIEXEC] --workdir DIR
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, run_deck, thermo_column  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks")


def mpi_prefix(mpiexec):
    prefix = [mpiexec, "-np", "2"]
    if os.geteuid() == 0:
        prefix += ["--allow-run-as-root"]
    return prefix + ["--oversubscribe"]


def run_ok(command, deck, workdir, variables):
    rc, text = run_deck(command, deck, workdir, variables)
    if rc != 0:
        raise Failure(f"{deck} {variables} exited with {rc}:\n{text[-3000:]}")
    return text


def warnings_in_log(workdir, prefix=""):
    """The WARNING lines of the run's log (run_deck's text holds them twice:
    screen and log)."""
    with open(os.path.join(workdir, "log.lammps"), encoding="utf-8", errors="replace") as f:
        return [x for x in f.read().splitlines() if x.startswith("WARNING: " + prefix)]


def last_snapshot(path, step):
    """The atom rows (as strings) of the dump snapshot of `step`."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    rows, at = None, None
    for k, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            at = int(lines[k + 1])
        elif line.startswith("ITEM: ATOMS") and at == step:
            rows = []
            for row in lines[k + 1:]:
                if not row.strip() or row.startswith("ITEM"):
                    break
                rows.append(row.split())
    if not rows:
        raise Failure(f"{path}: no snapshot of step {step}")
    return rows


# ------------------------------------------------------------ continuity

# stage names of continuity_lammps.in; continuity_liggghts.in numbers them
STAGES = {"whole": 0, "two": 1, "write": 2, "read": 3}


def continuity_run(a, command, workdir, stage, restart=None):
    deck = "continuity_lammps.in" if a.kind == "lammps" else "continuity_liggghts.in"
    nrun = 200 if a.scene == "cluster" else 150
    v = {"nrun": nrun, "out": "final.txt", "stage": stage if a.kind == "lammps" else STAGES[stage]}
    if a.kind == "lammps":
        v["scene"] = a.scene
    if restart:
        v["restart"] = restart
    run_ok(command, deck, workdir, v)
    if stage == "write":   # ends at step N
        return None
    return last_snapshot(os.path.join(workdir, "final.txt"), 2 * nrun)


def largest_relative_difference(a, b):
    worst = 0.0
    for ra, rb in zip(a, b):
        for x, y in zip(ra[1:10], rb[1:10]):   # positions, velocities, spins
            x, y = float(x), float(y)
            worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-300))
    return worst


def check_continuity(a, workdir):
    if a.kind == "liggghts" and a.scene != "pair":
        raise Failure("LIGGGHTS: scene pair only (its bond adapter has its own restart test)")
    one = [a.engine]
    ranks = {"1": one}
    if a.mpiexec:
        ranks["2"] = mpi_prefix(a.mpiexec) + [a.engine]
    d = lambda *parts: os.path.join(workdir, *parts)  # noqa: E731
    want = continuity_run(a, one, d("whole-1"), "whole")
    if not any(float(x) != 0.0 for row in want for x in row[10:13]):
        raise Failure("no force at step 2N: the scene does not test the history")
    results = []
    # LAMMPS bonds (the cluster): a run's setup pass evaluates the bonds'
    # damping at the velocities the run starts with, and the ghosts' loads
    # reach their atoms in another order on 2 ranks, so those agree to
    # within `bound`; one contact per atom (the pair) agrees bit for bit
    exact = a.scene == "pair"
    bound = 1e-12 if exact else 1e-7
    for n, command in ranks.items():
        if n == "2":
            results.append(("run 2N on 2 ranks", continuity_run(a, command, d("whole-2"), "whole"), exact))
        results.append((f"run N; run N on {n} rank(s)", continuity_run(a, command, d(f"two-{n}"), "two"), exact))
        continuity_run(a, command, d(f"write-{n}"), "write", restart="half.restart")
        restart = d(f"write-{n}", "half.restart")
        results.append((f"restart {n} -> 1", continuity_run(a, one, d(f"read-{n}-1"), "read", restart), exact))
        if n == "2":
            results.append(("restart 2 -> 2", continuity_run(a, command, d("read-2-2"), "read", restart), exact))
    failed = []
    for label, got, exact in results:
        worst = largest_relative_difference(want, got)
        same = got == want
        if same:
            print(f"{label}: bit for bit the uninterrupted run")
        else:
            print(f"{label}: differs, largest relative difference {worst:.3g}")
        if (exact and not same) or worst > bound:
            failed.append(label)
    if failed:
        raise Failure("not continuous: " + ", ".join(failed))


# ------------------------------------------------------------ timestep

# (model, dt, expected warnings in order: (phrase, atom types of the limit))
LAMMPS_TIMESTEP = [
    ("bond", 5e-6, [("EXCEEDS the critical step", "1 and 1"), ("EXCEEDS the critical step", "2 and 2")]),
    ("bond", 2e-6, [("exceeds the recommended step", "1 and 1"), ("exceeds the recommended step", "2 and 2")]),
    ("bond", 5e-7, []),
    ("voigt", 5e-5, [("EXCEEDS the critical step", "1 and 1"), ("EXCEEDS the critical step", "2 and 2")]),
    ("voigt", 2e-6, []),
]
# LIGGGHTS voigt: run 1, run 2 (same atoms), the insertion ten steps into run 2
LIGGGHTS_TIMESTEP = [
    (1e-3, [("EXCEEDS the critical step", "1 and 1")] * 2 + [("EXCEEDS the critical step", "2 and 2")]),
    (2e-6, []),
]
# LIGGGHTS model voigt + tangential history (kt, dt, expected warnings as
# above); spheres of 2 mm: normal critical step 4.6e-5 s, tangential
# 2 sqrt(m / 7 kt); the inserted spheres of 1 mm: normal 1.6e-5 s
LIGGGHTS_HANDED_ON_KT = [
    (1e6, 5e-6, [("EXCEEDS the critical step", "1 and 1")] * 2 + [("EXCEEDS the critical step", "2 and 2")]),
    (1e2, 8e-6, [("exceeds the recommended step", "2 and 2")]),
]


def check_timestep(a, workdir, handed_on=False):
    if a.kind == "lammps":
        cases = [(m, dt, want, f"pair granbond ({'bond/nonlinear' if m == 'bond' else 'voigt'}): time step", {})
                 for m, dt, want in LAMMPS_TIMESTEP]
    elif handed_on:
        cases = [(f"history-kt{kt:g}", dt, want, "model voigt: time step",
                  {"tan": "history", "roll": "off", "kt": kt}) for kt, dt, want in LIGGGHTS_HANDED_ON_KT]
    else:
        cases = [("voigt", dt, want, "model voigt: time step", {}) for dt, want in LIGGGHTS_TIMESTEP]
    failed = []
    for model, dt, want, prefix, extra in cases:
        deck = "timestep_lammps.in" if a.kind == "lammps" else "timestep_liggghts.in"
        v = dict(extra, dt=dt, nrun=20)
        if a.kind == "lammps":
            v["model"] = model
        run_ok([a.engine], deck, os.path.join(workdir, f"{model}-{dt:g}"), v)
        got = [line for line in warnings_in_log(os.path.join(workdir, f"{model}-{dt:g}")) if "time step" in line]
        ours = [line for line in got if prefix in line]
        ok = len(ours) == len(want) and all(
            phrase in line and f"atom types {types}" in line for line, (phrase, types) in zip(ours, want))
        print(f"{model} dt {dt:g}: {len(ours)} warning(s), {len(want)} expected" + "".join(
            f"\n    {line[:150]}" for line in ours))
        if not ok:
            failed.append(f"{model} dt {dt:g}")
        if not want and got:   # a safe step: no style warns
            failed.append(f"{model} dt {dt:g}: unexpected {got}")
    if failed:
        raise Failure("time-step warnings not as expected: " + "; ".join(failed))


# ------------------------------------------------------------ creation

# (case, deck variables, phrases of the expected findings, one list each)
CREATION = [
    ("consistent", {}, []),
    ("created-broken-always", {"cdist": 2.2e-3, "gap": 1e-4, "always": True},
     [["{create} 2.2e-3 m > {reach} 2.08e-3 m", "bonded and broken every step ({always} on)",
       "Set {create} <= {reach}"]]),
    ("created-broken-touching", {"cdist": 2.2e-3, "maxdist": 1.9e-3},
     [["{create} 2.2e-3 m > {reach} 1.9e-3 m", "in the step it forms",
       "a bond between touching spheres breaks too"]]),
    ("create-below-contact", {"cdist": 1.5e-3},
     [["{create} 1.5e-3 m is below the contact distance 2e-3 m", "overlapping by more than 5e-4 m"]]),
    ("create-step-0", {"ts": 0}, [["{ts} 0 is not after step 0", "{always} is off: no bond forms"]]),
    ("create-step-negative", {"ts": -5}, [["{ts} -5 is not after step 0"]]),
]
NAMES = {
    "liggghts": {"create": "createDistanceBondnonlinear", "reach": "maxDistanceBondnonlinear",
                 "always": "createBondAlways", "ts": "tsCreateBondnonlinear"},
    "lammps": {"create": "create_distance", "reach": "max_distance", "always": "create_always",
               "ts": "create_step"},
}


def check_creation(a, workdir):
    names = NAMES[a.kind]
    style = "cohesion bond/nonlinear (" if a.kind == "liggghts" else "pair granbond (bond/nonlinear) ("
    failed = []
    for case, v, want in CREATION:
        v = dict(v, nrun=20)
        always = v.pop("always", False)
        if a.kind == "liggghts":
            v["sw"] = "createBondAlways on" if always else "createBondAlways off"
        else:
            v["always"] = "yes" if always else "no"
        deck = f"creation_{a.kind}.in"
        run_ok([a.engine], deck, os.path.join(workdir, case), v)
        got = warnings_in_log(os.path.join(workdir, case), style)
        want = [[phrase.format(**names) for phrase in finding] for finding in want]
        ok = len(got) == len(want) and all(
            any(all(p in line for p in finding) for line in got) for finding in want)
        print(f"{case}: {len(got)} warning(s), {len(want)} expected" + "".join(f"\n    {g}" for g in got))
        if not ok:
            failed.append(case)
    if failed:
        raise Failure("creation-rule warnings not as expected: " + ", ".join(failed))


# ------------------------------------------------------------ renumber

def check_renumber(a, workdir):
    deck = f"renumber_{a.kind}.in"
    rc, out = run_deck([a.engine], deck, os.path.join(workdir, "compress-yes"), {"comp": "yes"})
    want = ["atoms changed their atom IDs", "delete_atoms ... compress no"]
    if rc == 0 or not all(w in out for w in want):
        raise Failure(f"compress yes: exit {rc}, the run did not end with the renumbering error:\n{out[-2500:]}")
    line = next(x for x in out.splitlines() if "changed their atom IDs" in x)
    print(f"compress yes: refused: {line.strip()[:160]}")
    run_ok([a.engine], deck, os.path.join(workdir, "compress-no"), {"comp": "no"})
    with open(os.path.join(workdir, "compress-no", "log.lammps"), encoding="utf-8") as f:
        fx3 = thermo_column(f.read(), "c_fx3")
    if len(fx3) < 2 or any(f != 0.0 for f in fx3):
        raise Failure(f"compress no: force on the never-bonded atom {fx3} (want 0 throughout)")
    print(f"compress no: runs on; force on the never-bonded atom 0 in all {len(fx3)} rows")


# ------------------------------------------------------------ lost

def check_lost(a, workdir):
    ranks = {"1": [a.engine]}
    if a.mpiexec:
        ranks["2"] = mpi_prefix(a.mpiexec) + [a.engine]
    for n, command in ranks.items():
        run_ok(command, f"lost_{a.kind}.in", os.path.join(workdir, f"np{n}"), {})
        warned = [x for x in warnings_in_log(os.path.join(workdir, f"np{n}")) if "bonds vanished" in x]
        if a.kind == "lammps":
            # no bond counter: each loss is warned with its number and cause
            warned = [x for x in warnings_in_log(os.path.join(workdir, f"np{n}")) if "bonds lost" in x]
            if (len(warned) != 2 or "2 bonds lost" not in warned[0] or "1 bonds lost" not in warned[1]
                    or "their atom left the system" not in warned[0] or "partner was not among" not in warned[1]):
                raise Failure(f"{n} rank(s): want a warning naming the 2 bonds of the deleted atom, then one "
                              f"naming the bond of the pair that left the box, each with its cause: {warned}")
            print(f"{n} rank(s): {' / '.join(w[:70] for w in warned)}")
            continue
        with open(os.path.join(workdir, f"np{n}", "log.lammps"), encoding="utf-8") as f:
            out = f.read()
        cols = [thermo_column(out, c) for c in ("c_bc[1]", "c_bc[2]", "c_bc[3]", "c_bc[7]")]
        rows = list(zip(*cols))
        if not rows:
            raise Failure(f"{n} rank(s): no counter rows")
        unbalanced = [r for r in rows if r[0] != r[1] + r[2] + r[3]]
        if unbalanced:
            raise Failure(f"{n} rank(s): created != broken + intact + lost in rows {unbalanced[:3]}")
        if rows[-1] != (3.0, 0.0, 0.0, 3.0):
            raise Failure(f"{n} rank(s): final created, broken, intact, lost {rows[-1]} (want 3 0 0 3)")
        if len(warned) != 1 or "2 bonds vanished" not in warned[0]:
            raise Failure(f"{n} rank(s): want one warning naming the 2 bonds of the deleted atom: {warned}")
        print(f"{n} rank(s): final counter {rows[-1]}; {warned[0]}")


def run(a):
    workdir = os.path.abspath(a.workdir)
    if a.mode == "continuity":
        check_continuity(a, workdir)
    elif a.mode == "timestep":
        check_timestep(a, workdir)
    elif a.mode == "timestep-kt":
        check_timestep(a, workdir, handed_on=True)
    elif a.mode == "creation":
        check_creation(a, workdir)
    elif a.mode == "renumber":
        check_renumber(a, workdir)
    elif a.mode == "lost":
        check_lost(a, workdir)
    else:
        raise Failure(f"unknown mode {a.mode}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    parser.add_argument("--scene", default="pair", choices=["pair", "cluster"])
    parser.add_argument("--mpiexec")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    main(lambda: run(args))
