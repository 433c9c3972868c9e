"""Restart files written with an older bond state layout are refused, never
misread: tests/adapters/data/state_layout_1_liggghts.restart (the flicked
chain, LIGGGHTS) and tests/adapters/data/state_layout_1_lammps.restart (the
wiggled pair, LAMMPS), both written by a granbond of layout 1 (15 slots per
bond, the bonds in the contact history), and
tests/adapters/data/state_layout_3_liggghts.restart (the flicked chain,
LIGGGHTS), written by a granbond of layout 3 (19 slots per bond, the bonds in
the bond store). LIGGGHTS refuses a contact history of another length
itself; pair_style granbond writes its state layout version into LAMMPS
restart files and refuses a file without it or with another; fix
granbond/bonds (the bond store of both engines) does the same for the
bonds it holds.
A file this granbond writes reads back (here for LIGGGHTS; the LAMMPS
restart ctest for LAMMPS).

usage: check_restart_layout.py --engine LIGGGHTS_GRANBOND [--lammps LMP_GRANBOND] --workdir DIR
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, judge_refusal, main, run_deck, run_ok  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "examples", "flicked_chain")
LAMMPS_DECKS = os.path.join(HERE, "decks")


def check(engine, lammps, workdir):
    failures = []
    rc, text = run_deck([engine], "restart_old_layout.in", os.path.join(workdir, "liggghts"),
                        {"restart": os.path.join(HERE, "data", "state_layout_1_liggghts.restart"),
                         "params": os.path.join(EXAMPLE, "params.in"), "here": EXAMPLE})
    judge_refusal("LIGGGHTS, older layout", rc, text, "contact history", failures)
    rc, text = run_deck([engine], "restart_old_layout.in", os.path.join(workdir, "liggghts_store"),
                        {"restart": os.path.join(HERE, "data", "state_layout_3_liggghts.restart"),
                         "params": os.path.join(EXAMPLE, "params.in"), "here": EXAMPLE})
    judge_refusal("LIGGGHTS, the store's older layout", rc, text, "older bond state layout", failures)
    # the control: the same deck continues a file this granbond wrote
    fresh = os.path.join(workdir, "liggghts_fresh")
    run_ok([engine], os.path.join(EXAMPLE, "in.flicked_chain"), fresh,
           {"params": os.path.join(EXAMPLE, "params.in"), "here": EXAMPLE, "nrun": 100, "restart": 1})
    run_ok([engine], "restart_old_layout.in", fresh,
           {"restart": os.path.join(fresh, "chain.restart"), "params": os.path.join(EXAMPLE, "params.in"),
            "here": EXAMPLE})
    print("ok: LIGGGHTS continues a restart file of this layout")
    if lammps:
        rc, text = run_deck([lammps], os.path.join(LAMMPS_DECKS, "restart_continue.in"),
                            os.path.join(workdir, "lammps"),
                            {"restart": os.path.join(HERE, "data", "state_layout_1_lammps.restart"),
                             "motion": "wiggle", "out": "second.txt", "nrun": 10})
        judge_refusal("LAMMPS, older layout", rc, text, "older layout", failures)
    if failures:
        raise Failure("; ".join(failures))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engine", required=True)
    parser.add_argument("--lammps")
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check(a.engine, a.lammps, a.workdir))
