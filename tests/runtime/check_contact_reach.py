"""LIGGGHTS's pair loop runs with the bonds' contact distance factor only in
a pass that can form a bond (cpp-adapter/liggghts/contact_reach.cpp); the
lists, the ghost atoms and the passes that form bonds keep the bonds' reach.

  reach   deck reach_liggghts.in on 1 and 2 ranks, with the store recounted
          after every pass (GRANBOND_CHECK_STORE): four pairs of spheres
          apart by twice the neighbour skin, but within the creation
          distance, each pair across the boundary between the ranks. Their
          bonds form at step 17, after list builds that follow passes in
          which no bond could form, and at step 4 in a second deck; all
          four stay intact, none lost, while the pairs move apart over
          later list builds and a second run's setup (each partner is a
          ghost of the other rank only thanks to the bonds' reach).

usage: check_contact_reach.py --mode reach --engine BIN --kind liggghts
                              [--mpiexec MPIEXEC] --workdir DIR
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, mpi_launcher, run_deck  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks")
PAIRS = 4


def launcher(a, n):
    return mpi_launcher(a.engine, a.mpiexec, n)


def rows(workdir):
    """step, atoms, created, broken, intact, lost of every thermo row."""
    with open(os.path.join(workdir, "log.lammps"), encoding="utf-8", errors="replace") as f:
        return [tuple(int(v) for v in row) for row in deck_runner.thermo_rows(f.read())]


def check_reach(a, workdir):
    ranks = (1, 2) if a.mpiexec else (1,)
    failures = []
    for n in ranks:
        for create in (17, 4):
            label = f"{n} ranks, bonds formed at step {create}"
            run_dir = os.path.join(workdir, f"r{n}-c{create}")
            rc, text = run_deck(launcher(a, n), "reach_liggghts.in", run_dir, {"create": create},
                                env={"GRANBOND_CHECK_STORE": "1"})
            if rc != 0:
                failures.append(f"{label}: exit {rc}:\n{text[-3000:]}")
                continue
            got = rows(run_dir)
            before = [r for r in got if r[0] < create]
            after = [r for r in got if r[0] >= create]
            if not before or not after:
                failures.append(f"{label}: no thermo rows on both sides of the creation step")
                continue
            early = [r for r in before if r[2] != 0]
            if early:
                failures.append(f"{label}: bonds before the creation step: {early[:3]}")
            # step atoms created broken intact lost: every bond formed at
            # the creation step and intact to the end of the second run
            wrong = [r for r in after if r[2:] != (PAIRS, 0, PAIRS, 0)]
            if wrong:
                failures.append(f"{label}: (step, atoms, created, broken, intact, lost) should read "
                                f"created = intact = {PAIRS}, none broken or lost: {wrong[:3]}")
            else:
                print(f"ok: {label}: {PAIRS} bonds intact over {len(after)} rows, "
                      f"the last at step {after[-1][0]}")
    if failures:
        raise Failure("; ".join(failures))


def parse():
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True, choices=["reach"])
    p.add_argument("--engine", required=True)
    p.add_argument("--kind", required=True, choices=["liggghts"])
    p.add_argument("--mpiexec")
    p.add_argument("--workdir", required=True)
    return p.parse_args()


if __name__ == "__main__":
    args = parse()
    main(lambda: check_reach(args, args.workdir))
