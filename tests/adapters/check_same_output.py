"""Two ways of running decks/bond_pull.in (distance mode, through the break)
give byte-identical per-step output.

- preload: build/bin/liggghts-granbond vs LD_PRELOAD=libgranbond_liggghts.so
  /usr/bin/liggghts; the stock binary alone must refuse the deck (so the test
  can tell the two apart).
- mpi: one rank vs `mpiexec -np 2` (the bonded pair straddles the ranks'
  boundary, its history crosses ranks with the atoms).

usage: check_same_output.py --mode preload --engine EXE --stock EXE --library SO --workdir DIR
       check_same_output.py --mode mpi --engine EXE --mpiexec MPIEXEC --workdir DIR
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, main, run_deck, run_ok  # noqa: E402

VARIABLES = {"out": "pull.txt", "nrun": 1000}


def output_of(command, workdir, env=None):
    run_ok(command, "bond_pull.in", workdir, VARIABLES, env)
    with open(os.path.join(workdir, "pull.txt"), "rb") as f:
        return f.read()


def compare(label_a, a, label_b, b):
    if a != b:
        raise Failure(f"{label_a} and {label_b} outputs differ")
    if len(a.splitlines()) < VARIABLES["nrun"]:
        raise Failure("output too short to compare")
    print(f"{label_a} == {label_b} ({len(a)} bytes)")


def check_preload(a, workdir):
    launcher = output_of([a.engine], os.path.join(workdir, "launcher"))
    preload = output_of([a.stock], os.path.join(workdir, "preload"), {"LD_PRELOAD": os.path.abspath(a.library)})
    compare("launcher", launcher, "LD_PRELOAD", preload)
    rc, _ = run_deck([a.stock], "bond_pull.in", os.path.join(workdir, "stock"), dict(VARIABLES, nrun=10))
    if rc == 0:
        raise Failure("the stock liggghts without the adapter accepted cohesion bond/nonlinear")
    print(f"stock binary alone: exit {rc}")


def check_mpi(a, workdir):
    serial = output_of([a.engine], os.path.join(workdir, "np1"))
    mpi_prefix = [a.mpiexec, "-np", "2"]
    if os.geteuid() == 0:
        mpi_prefix += ["--allow-run-as-root"]
    mpi_prefix += ["--oversubscribe"]
    parallel = output_of(mpi_prefix + [a.engine], os.path.join(workdir, "np2"))
    compare("1 rank", serial, "2 ranks", parallel)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=["preload", "mpi"], required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--stock")
    parser.add_argument("--library")
    parser.add_argument("--mpiexec")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    check = check_preload if args.mode == "preload" else check_mpi
    main(lambda: check(args, args.workdir))
