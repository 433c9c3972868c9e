"""The flicked chain (examples/flicked_chain): five bonded spheres along z,
the bottom one held, the top one flicked sideways, no damping, ku = 2 k.
The bending torque's two-sided hysteresis decides how the chain ends:

- historyReset on (the reference code's rule): every reversal through zero
  starts the other side afresh, so every swing dissipates and the chain
  comes to rest: the top sphere's amplitude over the last fifth of the run
  is below 5% of its first amplitude.
- history kept (the default): once the extremes stop growing the law is a
  fixed, single-valued function of the angle, so the chain keeps swinging
  (last-fifth amplitude above 15% of the first); a bond that stays on one
  side oscillates on that side's unloading line about the residual angle
  where the line crosses zero torque, (1 - k/ku) x the side's extreme
  (here half of it). Its mean angle over the last fifth must equal that to
  5% (the coupling to its neighbours and the square-root compression make
  the swing slightly asymmetric), and at least two bonds must do so.
- LIGGGHTS and LAMMPS (--lammps) give the same rows to the printed digit.

usage: check_flicked_chain.py --engine LIGGGHTS_GRANBOND [--lammps LMP_GRANBOND] --workdir DIR
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, main, run_ok  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "examples", "flicked_chain")
sys.path.insert(0, EXAMPLE)
from chain_analysis import last_fifth, load_bond_angles, load_chain, residual, top_amplitudes  # noqa: E402


def run(command, deck, workdir, reset):
    run_ok(command, os.path.join(EXAMPLE, deck), workdir,
           {"params": os.path.join(EXAMPLE, "params.in"), "here": EXAMPLE, "reset": reset})
    return load_chain(os.path.join(workdir, "chain.txt"))


def check_rest(rows):
    first, last = top_amplitudes(rows)
    if not last < 0.05 * first:
        raise Failure(f"historyReset on: the top sphere still swings {last:.3g} m over the last fifth, "
                      f"{last / first:.1%} of its first amplitude {first:.3g} m (limit 5%)")
    print(f"historyReset on: at rest, last-fifth amplitude {last / first:.2%} of the first ({first:.3g} m)")


def check_residual(rows, bonds):
    first, last = top_amplitudes(rows)
    if not last > 0.15 * first:
        raise Failure(f"history kept: the chain came to rest ({last / first:.1%} of the first amplitude); "
                      f"with a fixed elastic law it must keep swinging")
    settled = 0
    for key in sorted(bonds):
        mean, predicted, (lo, hi) = residual(bonds[key])
        one_side = lo * hi > 0.0
        note = ""
        if one_side:
            if abs(mean - predicted) > 0.05 * abs(predicted):
                raise Failure(f"bond {key}: mean bending angle {mean:.5g} over the last fifth, the law's "
                              f"residual (1 - k/ku) x extreme is {predicted:.5g}")
            settled += 1
        else:
            note = " (swings across both sides: elastic over the whole loop)"
        print(f"bond {key[0]}-{key[1]}: mean bend {mean:.5g}, residual {predicted:.5g}, "
              f"range {lo:.4g}..{hi:.4g}{note}")
    if settled < 2:
        raise Failure(f"only {settled} bonds stay on one side: nothing checks the residual angle")
    print(f"history kept: still swinging at {last / first:.1%} of the first amplitude")


def same_rows(a, b, what):
    by_step = {int(r[0]): r for r in b}
    common = [r for r in a if int(r[0]) in by_step]
    if len(common) < len(a) - 1:
        raise Failure(f"{what}: only {len(common)} of {len(a)} steps in both outputs")
    for r in common:
        if r != by_step[int(r[0])]:
            raise Failure(f"{what}: step {int(r[0])} differs:\n  LIGGGHTS {r}\n  LAMMPS   {by_step[int(r[0])]}")
    print(f"{what}: LIGGGHTS and LAMMPS print the same {len(common)} rows")


def check(engine, lammps, workdir):
    kept = run([engine], "in.flicked_chain", os.path.join(workdir, "liggghts_off"), "off")
    check_residual(kept, load_bond_angles(os.path.join(workdir, "liggghts_off", "bond_angles.txt")))
    reset = run([engine], "in.flicked_chain", os.path.join(workdir, "liggghts_on"), "on")
    check_rest(reset)
    if lammps:
        for name, rows in (("off", kept), ("on", reset)):
            other = run([lammps], "in.flicked_chain_lammps", os.path.join(workdir, f"lammps_{name}"), name)
            same_rows(rows, other, f"history reset {name}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engine", required=True)
    parser.add_argument("--lammps")
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check(a.engine, a.lammps, a.workdir))
