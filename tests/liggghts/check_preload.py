"""LD_PRELOAD of the adapter into the stock liggghts behaves like the launcher.

Runs decks/bond_pull.in (distance mode, through the break) with
build/bin/liggghts-granbond and with LD_PRELOAD=libgranbond_liggghts.so
/usr/bin/liggghts, and requires byte-identical per-step output, plus the
stock binary alone refusing the deck (so the test can tell the two apart).

usage: check_preload.py --engine EXE --stock EXE --library SO --workdir DIR
"""

import argparse
import os

from liggghts_run import Failure, main, run_deck, run_ok


def check(engine, stock, library, workdir):
    variables = {"out": "pull.txt", "nrun": 1000}
    launcher_dir = os.path.join(workdir, "launcher")
    preload_dir = os.path.join(workdir, "preload")
    run_ok([engine], "bond_pull.in", launcher_dir, variables)
    run_ok([stock], "bond_pull.in", preload_dir, variables, env={"LD_PRELOAD": os.path.abspath(library)})
    with open(os.path.join(launcher_dir, "pull.txt"), "rb") as f:
        a = f.read()
    with open(os.path.join(preload_dir, "pull.txt"), "rb") as f:
        b = f.read()
    if a != b:
        raise Failure("launcher and LD_PRELOAD outputs differ")
    if len(a.splitlines()) < 1000:
        raise Failure("output too short to compare")
    rc, text = run_deck([stock], "bond_pull.in", os.path.join(workdir, "stock"), dict(variables, nrun=10))
    if rc == 0:
        raise Failure("the stock liggghts without the adapter accepted cohesion bond/nonlinear")
    print(f"identical output ({len(a)} bytes); stock binary alone: exit {rc}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engine", required=True)
    parser.add_argument("--stock", required=True)
    parser.add_argument("--library", required=True)
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check(a.engine, a.stock, a.library, a.workdir))
