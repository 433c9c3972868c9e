"""Engine-level checks of what a run does between and around runs
(docs/runtime-checks.md), for LAMMPS (lmp-granbond) and LIGGGHTS
(liggghts-granbond). One claim per mode:

  continuity  free motion (fix nve/sphere) continued by a second `run` or
              by write_restart + read_restart ends, at step 2N, in the state
              of the uninterrupted run: bit for bit (17 digits of every
              position, velocity, spin, force and torque) for run N + run N
              on 1 and 2 ranks, and for restarts 1 -> 1 and 2 -> 1. A
              restart 2 -> 2 is held to 1e-12 (relative) where several
              loads sum on one atom (the cluster): LAMMPS orders the
              neighbour list of the restarted run differently, so those
              sums round differently; one load per atom (the pair) is held
              bit for bit there too. Scenes: --scene cluster (LAMMPS: 8
              bonded spheres, bond damping on) and --scene pair (a voigt
              pair, sliding and rolling; both engines).

usage: check_runtime.py --mode MODE --engine BIN --kind lammps|liggghts
                        [--scene S] [--mpiexec MPIEXEC] --workdir DIR
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "liggghts"))

import liggghts_run  # noqa: E402
from liggghts_run import Failure, main, run_deck  # noqa: E402

liggghts_run.DECKS = os.path.join(HERE, "decks")


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
    for n, command in ranks.items():
        if n == "2":
            results.append(("run 2N on 2 ranks", continuity_run(a, command, d("whole-2"), "whole"), True))
        results.append((f"run N; run N on {n} rank(s)", continuity_run(a, command, d(f"two-{n}"), "two"), True))
        continuity_run(a, command, d(f"write-{n}"), "write", restart="half.restart")
        restart = d(f"write-{n}", "half.restart")
        results.append((f"restart {n} -> 1", continuity_run(a, one, d(f"read-{n}-1"), "read", restart), True))
        if n == "2":
            exact = a.scene == "pair"
            results.append(("restart 2 -> 2", continuity_run(a, command, d("read-2-2"), "read", restart), exact))
    failed = []
    for label, got, exact in results:
        worst = largest_relative_difference(want, got)
        same = got == want
        if same:
            print(f"{label}: bit for bit the uninterrupted run")
        else:
            print(f"{label}: differs, largest relative difference {worst:.3g}")
        if (exact and not same) or worst > 1e-12:
            failed.append(label)
    if failed:
        raise Failure("not continuous: " + ", ".join(failed))


def run(a):
    workdir = os.path.abspath(a.workdir)
    if a.mode == "continuity":
        check_continuity(a, workdir)
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
