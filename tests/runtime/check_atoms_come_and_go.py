"""Engine-level checks that bonds belong to the atoms that formed them when
atoms come and go between runs (docs/runtime-checks.md, "Atoms created
between runs"), for LAMMPS (lmp-granbond) and LIGGGHTS (liggghts-granbond).
One claim per mode:

  come-go     a bonded, stretched block (come_go_*.in) on 1 to --ranks
              ranks. One sphere created far from it between two runs
              leaves the block's trajectory as it is without that sphere
              (to round-off), and no bond changes. Atoms deleted with
              `compress no` (the highest ID, an inner atom, the top layer
              of highest IDs), then smaller spheres created on their sites,
              inside the former partners' reach and touching nothing (the
              engines hand out the freed IDs again): the new spheres feel
              no force, and every other atom moves as in the run where the
              atoms were only deleted. The bonds counted: LIGGGHTS's
              bond/counter keeps created = broken + intact + lost, with the
              same intact bonds as without the new spheres; LAMMPS warns
              the same vanished bonds with and without them. A bonded atom
              moved far from its partners between runs (`set atom`): its
              bonds vanish, warned with that cause named (LIGGGHTS: lost).
  thin-slab   a periodic box one or two lattice sites thick (a sphere meets
              its own image, or one partner twice) ends the run with an
              error naming the box length and the reach; three sites run.
  fractional  LIGGGHTS: a fractional tsCreateBondnonlinear ends the run
              naming the parameter (it was truncated: 0.999 meant step 0).

usage: check_atoms_come_and_go.py --mode MODE --engine BIN --kind lammps|liggghts
                                  [--mpiexec MPIEXEC --ranks N] --workdir DIR
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from check_runtime import last_snapshot, run_ok, thermo_column, warnings_in_log  # noqa: E402
from deck_runner import Failure, main, mpi_launcher, run_deck  # noqa: E402

N1, N2 = 20, 40
VACANCIES = {1: "the highest ID", 2: "an inner atom", 3: "the top layer"}


def launcher(a, n):
    return mpi_launcher(a.engine, a.mpiexec, n)


def come_go_run(a, n, case, vac, workdir):
    text = run_ok(launcher(a, n), f"come_go_{a.kind}.in", workdir, {"case": case, "vac": vac, "n1": N1, "n2": N2})
    atoms = {int(r[0]): [float(x) for x in r[1:]] for r in last_snapshot(os.path.join(workdir, "final.txt"),
                                                                        N1 + N2)}
    # LAMMPS tells each loss with its causes, LIGGGHTS says they vanished
    vanished = [w for w in warnings_in_log(workdir) if "bonds vanished" in w or "bonds lost" in w]
    counts = None
    if a.kind == "liggghts":
        cols = [thermo_column(text, c) for c in ("c_bc[1]", "c_bc[2]", "c_bc[3]", "c_bc[7]")]
        counts = list(zip(*cols))
    return atoms, vanished, counts


def lost_count(warning):
    """The number of bonds a loss warning names."""
    words = warning.split()
    for k, w in enumerate(words[1:], 1):
        if w == "bonds" and words[k + 1] in ("vanished", "lost"):
            return words[k - 1]
    return warning


def largest_difference(want, got, ids):
    """Largest difference of positions, velocities and spins (relative to
    the largest magnitude of each quantity over the atoms) and of forces."""
    worst = 0.0
    for lo, hi in ((0, 3), (3, 6), (6, 9), (9, 12)):
        scale = max(max(abs(x) for x in want[i][lo:hi]) for i in ids) or 1.0
        for i in ids:
            for x, y in zip(want[i][lo:hi], got[i][lo:hi]):
                worst = max(worst, abs(x - y) / scale)
    return worst


def compare(label, base, case, a, new_ids=()):
    """`case` against `base`: the atoms they share move alike, the new ones
    feel nothing, and the bond counts agree."""
    (want, want_vanished, want_counts), (got, got_vanished, got_counts) = base, case
    problems = []
    shared = sorted(set(want) & set(got))
    if len(shared) != len(want):
        problems.append(f"{len(want) - len(shared)} atoms of the baseline missing")
    worst = largest_difference(want, got, shared)
    if worst > 1e-12:
        problems.append(f"the atoms the change did not touch differ by {worst:.3g} (relative)")
    for i in new_ids:
        force = max(abs(x) for x in got[i][9:12])
        if force != 0.0:
            problems.append(f"the new atom {i} feels a force {force:.3g} N")
    # the same bonds, whatever the cause (a new atom that takes over a
    # deleted atom's id is told as such)
    if [lost_count(w) for w in got_vanished] != [lost_count(w) for w in want_vanished]:
        problems.append(f"vanished-bond warnings {got_vanished} differ from {want_vanished}")
    if a.kind == "liggghts":
        unbalanced = [r for r in got_counts if r[0] != r[1] + r[2] + r[3]]
        if unbalanced:
            problems.append(f"created != broken + intact + lost in rows {unbalanced[:3]}")
        if got_counts[-1] != want_counts[-1]:
            problems.append(f"final created, broken, intact, lost {got_counts[-1]}, want {want_counts[-1]}")
    detail = f"largest difference {worst:.3g}"
    if a.kind == "liggghts":
        detail += f", counter {tuple(int(x) for x in got_counts[-1])}"
    print(f"{label}: " + ("; ".join(problems) if problems else f"as the baseline ({detail})"))
    return [f"{label}: {p}" for p in problems]


def check_come_go(a, workdir):
    ranks = [1] + (list(range(2, a.ranks + 1)) if a.mpiexec else [])
    failed = []
    for n in ranks:
        d = lambda name: os.path.join(workdir, f"np{n}", name)  # noqa: E731
        none = come_go_run(a, n, "none", 1, d("none"))
        far = come_go_run(a, n, "far", 1, d("far"))
        if a.kind == "liggghts" and none[2][-1][2] == 0:
            raise Failure("the block has no intact bonds: the scene does not test them")
        failed += compare(f"{n} rank(s), a sphere created far away", none, far, a,
                          sorted(set(far[0]) - set(none[0])))
        if n == 1:
            failed += check_moved(a, d("moved"))
        for vac, where in VACANCIES.items():
            deleted = come_go_run(a, n, "delete", vac, d(f"delete-{vac}"))
            refill = come_go_run(a, n, "refill", vac, d(f"refill-{vac}"))
            if not deleted[1]:
                raise Failure(f"{where}: no bond vanished with the deleted atoms: the scene does not test them")
            new = sorted(set(refill[0]) - set(deleted[0]))
            failed += compare(f"{n} rank(s), {where} deleted and its site refilled (new IDs {new[:3]}"
                              f"{'...' if len(new) > 3 else ''})", deleted, refill, a, new)
    if failed:
        raise Failure("; ".join(failed))


def check_moved(a, workdir):
    """A corner atom moved far from its 3 partners between runs: its bonds
    vanish, warned (and, LIGGGHTS, counted as lost) with the cause named."""
    _, vanished, counts = come_go_run(a, 1, "moved", 1, workdir)
    said = "3 bonds lost" if a.kind == "lammps" else "3 bonds vanished"
    ok = len(vanished) == 1 and said in vanished[0] and "moved farther than the bond's reach" in vanished[0]
    if a.kind == "liggghts":
        ok = ok and counts[-1][3] == 3 and all(r[0] == r[1] + r[2] + r[3] for r in counts)
    print(f"a bonded atom moved far between runs: {vanished}" + (f", counter {counts[-1]}" if counts else ""))
    return [] if ok else [f"moved atom: warnings {vanished}, counter {counts and counts[-1]}"]


def check_thin_slab(a, workdir):
    failed = []
    for nz in (1, 2, 3):
        rc, out = run_deck([a.engine], f"thin_slab_{a.kind}.in", os.path.join(workdir, f"nz{nz}"), {"nz": nz})
        error = next((x for x in out.splitlines() if x.startswith("ERROR")), "")
        length = f"the periodic box is {0.002 * nz:g} long in z"
        if nz < 3:
            ok = rc != 0 and length in error and "twice the neighbour reach" in error
        else:
            ok = rc == 0 and not error
        print(f"{nz} site(s) thick: exit {rc} {error[:150]}")
        if not ok:
            failed.append(f"{nz} site(s): exit {rc}, {error or 'no error'}")
    if failed:
        raise Failure("thin periodic boxes not as expected: " + "; ".join(failed))


def check_fractional(a, workdir):
    if a.kind != "liggghts":
        raise Failure("LIGGGHTS only (LAMMPS parses create_step as an integer)")
    rc, out = run_deck([a.engine], "lost_liggghts.in", os.path.join(workdir, "fractional"), {"ts": 0.999})
    error = next((x for x in out.splitlines() if x.startswith("ERROR")), "")
    print(f"tsCreateBondnonlinear 0.999: exit {rc} {error[:160]}")
    if rc == 0 or "tsCreateBondnonlinear" not in error or "0.999" not in error:
        raise Failure(f"a fractional creation step was not refused by name: exit {rc}, {error or 'no error'}")


def run(a):
    workdir = os.path.abspath(a.workdir)
    if a.mode == "come-go":
        check_come_go(a, workdir)
    elif a.mode == "thin-slab":
        check_thin_slab(a, workdir)
    elif a.mode == "fractional":
        check_fractional(a, workdir)
    else:
        raise Failure(f"unknown mode {a.mode}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    parser.add_argument("--mpiexec")
    parser.add_argument("--ranks", type=int, default=4)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    main(lambda: run(args))
