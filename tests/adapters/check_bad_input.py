"""A bad bond/nonlinear property ends the run with an error that names it.

Each case runs decks/bond_pull.in with one value overridden and expects: a
non-zero exit code, no signal, and an ERROR line naming the property (the
LIGGGHTS-INL fix property/global name users write in their decks) and the
command (`cohesion bond/nonlinear`), and no C entry of the core.

usage: check_bad_input.py --engine EXE --workdir DIR
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, judge_refusal, main, run_deck  # noqa: E402

CASES = [
    # (label, overridden variables, text the ERROR line must contain)
    ("negative stiffness", {"k_fn2": -1e9}, "stiffnessPerUnitAreaK_fn2"),
    ("damping ratio eta >= 1", {"eta": 1.0}, "dampingNormalForceBondnonlinear"),
    ("radius multiplier 0", {"lambda": 0}, "radiusMultiplierBondnonlinear"),
    ("unloading softer than loading (ku < k)", {"ku_fn2": 5e8}, "stiffnessPerUnitAreaKu_fn2"),
    ("missing property", {"name_kfn1": "someOtherName"}, "stiffnessPerUnitAreaK_fn1"),
    ("bond reach above 10 diameters", {"maxdist": 0.05}, "maxDistanceBondnonlinear"),
    ("stress mode reach above 10 diameters", {"stress": "on", "sigma": 1e8}, "maxSigmaBondnonlinear"),
]


def check_all(engine, workdir):
    failures = []
    for index, (label, variables, name) in enumerate(CASES):
        rc, text = run_deck([engine], "bond_pull.in", os.path.join(workdir, f"case{index}"),
                            dict(variables, nrun=10))
        judge_refusal(label, rc, text, name, failures, command="cohesion bond/nonlinear")
    if failures:
        raise Failure("\n".join(failures))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engine", required=True)
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check_all(a.engine, a.workdir))
