"""A bond pulled apart (or pushed together) at constant velocity by fix move:
two spheres (decks/bond_pull.in) or a sphere and a wall (decks/wall_pull.in).

Claims (docs/models/bond-nonlinear.md), every step, to 1e-6 relative:
- virgin tension: the force is k_fn2 A delta along the centre line
  (delta = r0 - r, A = pi (lambda min R)^2), equal and opposite on the spheres;
- virgin compression (mode `compression`, spheres overlapping): k_fn1 A
  delta^1/2 and nothing of the Hertz contact: the intact bond replaces it;
- the bond is created at step tsCreate = 1 with r0 = r (zero force then);
- distance mode: it breaks in the first step with r > maxDistance;
  stress mode: in the first step with sigma = k_fn2 |delta| >= sigma_max
  (times gamma under ratioTensionCompressionBond, delta < 0);
- from the break on the force is exactly zero; for a bond that breaks in
  compression (mode `compression-break`) it is, from the break step on,
  the Hertz contact's alone: equal to a run of the same motion without
  bonds (the step that breaks the bond applies the contact loads).
- the pressure's virial (compute pressure ... virial) is the pair's
  (x_1 - x_2) . f_1 / (3 V) (V: the box) every step, to 1e-9 relative.
A wall acts as a sphere of the particle's radius mirrored behind the contact
point of creation, so there r = z + R for a sphere above the plane z = 0.

usage: check_bond_pull.py --mode MODE --engine EXE --workdir DIR
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, main, read_table, run_ok  # noqa: E402

RELATIVE_TOLERANCE = 1e-6

PARAMS = {
    "diameter": 2e-3,
    "lambda": 0.5,
    "k_fn1": 1e9,
    "k_fn2": 1e9,
    "vpull": 0.1,        # m/s, 1e-7 m per step of 1e-6 s
    "nrun": 1000,
    # not a multiple of the 1e-7 m step: the break step is unambiguous
    "maxdist": 2.08050e-3,
    "sigma": 5.005e4,
    "gamma": 0.5,
}
MODES = {
    "distance": {"stress": "off", "ratio": "off"},
    "stress": {"stress": "on", "ratio": "off"},
    "stress-ratio": {"stress": "on", "ratio": "on"},
    # pushed 5e-5 m into each other: no break
    "compression": {"stress": "off", "ratio": "off", "vpull": -0.1, "nrun": 500},
    # pushed together until k_fn1 delta^1/2 reaches sigma (delta = 2.5e-5 m, step ~250)
    "compression-break": {"stress": "on", "ratio": "off", "vpull": -0.1, "nrun": 500, "sigma": 5.0005e6},
    "wall-mesh": {"mesh": 1},
    "wall-primitive": {"mesh": 0},
}


def pair_samples(rows):
    """(step, r, unit vector from 1 to 2, [(name, force, sign)]): sphere 2
    gets +Fn u, sphere 1 gets -Fn u."""
    for row in rows:
        x1, x2 = row[1:4], row[4:7]
        d = [b - a for a, b in zip(x1, x2)]
        r = math.sqrt(sum(c * c for c in d))
        yield int(row[0]), r, [c / r for c in d], [("f2", row[10:13], 1.0), ("f1", row[7:10], -1.0)]


BOX_VOLUME = 0.02 ** 3   # bond_pull.in


def verify_virial(rows):
    """Column 13: the virial pressure of the only pair."""
    loaded = 0
    for row in rows:
        d = [a - b for a, b in zip(row[1:4], row[4:7])]
        want = sum(a * f for a, f in zip(d, row[7:10])) / (3 * BOX_VOLUME)
        if abs(row[13] - want) > 1e-9 * abs(want) + 1e-300:
            raise Failure(f"step {int(row[0])}: virial pressure {row[13]!r}, the pair's force gives {want!r}")
        loaded += want != 0.0
    if loaded < 100:
        raise Failure(f"only {loaded} steps with a load: the virial is not tested")
    return f"virial = the pair's on {loaded} loaded steps"


def wall_samples(rows, radius):
    """The wall plane is z = 0 and the sphere moves along +z only."""
    for row in rows:
        z = row[3]
        yield int(row[0]), z + radius, [0.0, 0.0, 1.0], [("f", row[4:7], 1.0)]


def verify(samples, mode, contact_rows=None):
    radius = PARAMS["diameter"] / 2
    area = math.pi * (PARAMS["lambda"] * radius) ** 2

    def normal_force(delta):        # virgin branches, > 0 repulsive
        return PARAMS["k_fn1"] * area * math.sqrt(delta) if delta > 0 else PARAMS["k_fn2"] * area * delta

    params = dict(PARAMS, **MODES[mode])
    stress_mode = params.get("stress") == "on"
    r0 = None
    r = None
    broken_at = None
    checked = 0
    for step, r, unit, forces in samples:
        if step == 0:
            continue
        if step == 1:
            r0 = r                                  # created this step
        delta = r0 - r
        if broken_at is None:
            if stress_mode:
                stretched = delta < 0
                sigma = abs(normal_force(delta)) / area
                strength = params["sigma"] * (params["gamma"] if stretched and mode == "stress-ratio" else 1.0)
                breaks = sigma >= strength
            else:
                breaks = r > PARAMS["maxdist"]
            if breaks:
                broken_at = step
        if broken_at is not None and contact_rows is not None:
            want = contact_rows[step]
            if not any(want[7:13]):
                raise Failure(f"step {step}: the run without bonds has no contact force: not an overlap")
            for name, got, _ in forces:
                ref = want[10:13] if name == "f2" else want[7:10]
                if got != ref:
                    raise Failure(f"step {step} (bond broke at {broken_at}): {name} = {got}, the Hertz contact "
                                  f"alone (run without bonds) gives {ref}")
            continue
        if broken_at is not None:
            if any(any(f) for _, f, _ in forces):
                raise Failure(f"step {step}: force {forces} on a broken bond (broke at {broken_at})")
            continue
        fn = normal_force(delta)
        for name, got, sign in forces:
            for c in range(3):
                want = sign * fn * unit[c]
                if abs(got[c] - want) > RELATIVE_TOLERANCE * abs(fn) + 1e-300:
                    raise Failure(f"step {step} (r={r:.9g}, delta={delta:.6g}): {name}[{c}] = {got[c]!r}, "
                                  f"the closed form gives {want!r}")
        checked += 1
    if mode == "compression":
        if broken_at is not None or r >= PARAMS["diameter"] - 4e-5:
            raise Failure(f"compression run: break at {broken_at}, final r {r}: not the intended overlap")
        return f"closed form matched on {checked} overlapping steps"
    if broken_at is None:
        raise Failure("the bond never reached its breaking point: the deck does not test breakage")
    if contact_rows is not None:
        return (f"closed form matched on {checked} steps, broke in compression at step {broken_at}, "
                f"then the Hertz contact's forces exactly (from the break step on)")
    if checked < 100 or broken_at > step - 100:
        raise Failure(f"too few steps before ({checked}) or after the break (step {broken_at})")
    return f"closed form matched on {checked} steps, broke at step {broken_at}, zero force after"


def check_run(engine, mode, workdir):
    variables = dict(PARAMS)
    variables.update(MODES[mode])
    variables["out"] = "pull.txt"
    wall = mode.startswith("wall")
    run_ok([engine], "wall_pull.in" if wall else "bond_pull.in", workdir, variables)
    rows = read_table(os.path.join(workdir, "pull.txt"))
    if len(rows) < variables["nrun"]:
        raise Failure(f"only {len(rows)} output rows")
    samples = wall_samples(rows, PARAMS["diameter"] / 2) if wall else pair_samples(rows)
    contact_rows = None
    if mode == "compression-break":
        run_ok([engine], "bond_pull.in", workdir, dict(variables, bonds=0, out="contact.txt"))
        contact_rows = {int(row[0]): row for row in read_table(os.path.join(workdir, "contact.txt"))}
    print(f"{mode}: {verify(samples, mode, contact_rows)}")
    if not wall:
        print(f"{mode}: {verify_virial(rows)}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=sorted(MODES), required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check_run(a.engine, a.mode, a.workdir))
