"""The bond makes no energy of its own, in LIGGGHTS (liggghts-granbond) and
LAMMPS (lmp-granbond) (docs/models/bond-nonlinear.md "Energy",
docs/speed-accuracy.md "The square root at zero compression"). Decks in
decks/energy/.

  tetra      four spheres in a tetrahedron, six bonds formed at zero
             compression, one sphere started at 0.1 m/s, nothing else
             acting: the kinetic energy can never exceed its start. The
             recommended step is read from the warning of a run far above
             it; then at 0.2, 0.5 and 0.99 of it each deck either keeps its
             kinetic energy at or below the start or is warned at its start
             naming the regularisation (compression_linear_below /
             compressionLinearBelowBondnonlinear): the elastic bonds under
             the plain square root (warned at every step), a little
             hysteresis (ku = 1.1 k: warned above 0.2 of the step). Decks
             that are stable are not warned: the regularisation the warning
             suggests, and ku = 2 k with damping 0.01.
  bendcycle  sphere 2 held, sphere 1 turned so that the bending angle runs
             a set-up bend and three closed squares off the set-up's plane,
             both ways round: the bond's work on the driver (the trapezoid
             sum of torque . spin over the steps) is <= 0 in the cycles that
             start and end at the same history (2 and 3), and the first,
             which grows the history, dissipates.

usage: check_energy.py --mode tetra|bendcycle --engine BIN --kind lammps|liggghts --workdir DIR
"""

import argparse
import math
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, run_deck  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks", "energy")
NUMBER = r"([0-9.]+(?:e[-+]?[0-9]+)?)"
TEND = 0.05  # s: the elastic deck gains x5 at 0.2 of the step in it
# Kinetic energy over its start that counts as a gain: a stable run stays at
# or below its start (the sweeps behind REST_STABLE read exactly 1).
GAIN = 1.001
REGULARISATION = {"lammps": "compression_linear_below", "liggghts": "compressionLinearBelowBondnonlinear"}


def tetra_deck(kind):
    return "energy_tetra.in" if kind == "lammps" else "energy_tetra_liggghts.in"


def run_tetra(a, workdir, name, dt, tend, variables):
    rc, text = run_deck([a.engine], tetra_deck(a.kind), os.path.join(workdir, name),
                        dict({"dt": dt, "tend": tend, "every": 20}, **variables))
    if rc != 0:
        raise Failure(f"{name}: exit {rc}:\n{text[-2000:]}")
    warnings = [line for line in text.splitlines() if line.startswith("WARNING") and "bond/nonlinear" in line]
    # thermo rows: the last column is the kinetic energy (translational + rotational)
    energy = [row[-1] for header, rows in deck_runner.thermo_blocks(text) if len(header) == 5 for _, row in rows]
    if not energy or not energy[0] > 0:
        raise Failure(f"{name}: no kinetic energy in the thermo output:\n{text[-2000:]}")
    return max(energy) / energy[0], warnings


def recommended_step(a, workdir, name, variables):
    """The bond type's recommended step, from the warning of a run far above
    it (where bonds at rest limit it, the step they are measured against),
    and the warning."""
    _, warnings = run_tetra(a, workdir, name + "_far", 1e-4, 1e-4, variables)
    said = " ".join(warnings)
    found = re.search(r"of the recommended step " + NUMBER + " s", said) or \
        re.search(r"Use timestep <= " + NUMBER + " s", said)
    if not found:
        raise Failure(f"{name}: no recommended step in the warnings: {warnings}")
    return float(found.group(1)), said


def check_tetra(a, workdir):
    clb = REGULARISATION[a.kind]
    # The regularisation the warning of the elastic deck suggests.
    _, said = recommended_step(a, workdir, "suggested", {})
    suggested = re.search(r"the linear regularisation " + clb + " " + NUMBER + " m", said)
    if not suggested:
        raise Failure(f"the warning suggests no {clb}: {said}")
    failed = []
    cases = [
        # (name, deck variables, fractions, warned expected: True / False / None (either))
        ("elastic", {}, (0.2, 0.5, 0.99), True),
        ("ku_1.1k", {"fu": 1.1}, (0.1, 0.5), None),
        ("regularised", {"eps": suggested.group(1)}, (0.2, 0.5, 0.99), False),
        ("ku_2k_eta_0.01", {"fu": 2, "eta": 0.01}, (0.99,), False),
    ]
    for name, variables, fractions, warned_expected in cases:
        step, _ = recommended_step(a, workdir, name, variables)
        for fraction in fractions:
            label = f"{name} at {fraction} of {step:g} s"
            gain, warnings = run_tetra(a, workdir, f"{name}_{fraction}", fraction * step, TEND, variables)
            warned = any(clb in w for w in warnings)
            print(f"{label}: max KE/KE(0) {gain:.4g}, warned {warned}")
            if gain > GAIN and not warned:
                failed.append(f"{label}: kinetic energy x{gain:.4g} of its start, and no warning names {clb}")
            if warned_expected is not None and warned != warned_expected:
                failed.append(f"{label}: warned {warned}, expected {warned_expected}: {warnings}")
            if warned_expected is False and warnings:
                failed.append(f"{label}: a stable deck is warned: {warnings}")
    if failed:
        raise Failure("; ".join(failed))


def bend_deck(kind):
    return "energy_bendcycle.in" if kind == "lammps" else "energy_bendcycle_liggghts.in"


def cycle_work(workdir, table, dt):
    """Work of the bond on the driver per tag of legs.in (setup, cycle1, ...):
    the trapezoid sum of T . omega dt over the steps of each leg."""
    rows = {}
    with open(os.path.join(workdir, table)) as f:
        for line in f:
            fields = line.split()
            if fields and not line.startswith("#"):
                rows.setdefault(int(fields[0]), [float(x) for x in fields[1:]])
    with open(os.path.join(workdir, "legs.in")) as f:
        legs = f.read().splitlines()
    steps = [int(line.split()[1]) for line in legs if line.startswith("run ")]
    tags = [re.search(r"LEG \d+ (\S+)", line).group(1) for line in legs if line.startswith("print")]
    start, work = 2, {}
    for n, tag in zip(steps, tags):
        w = 0.0
        for s in range(start + 1, start + n + 1):
            before = rows.get(s - 1, [0.0] * 7)[1:4]
            after, spin = rows[s][1:4], rows[s][4:7]
            w += sum(0.5 * (x + y) * o for x, y, o in zip(before, after, spin)) * dt
        work[tag] = work.get(tag, 0.0) + w
        start += n
    return work


def check_bendcycle(a, workdir):
    dt, kb, a_setup, rb = 1e-7, 1e10, 0.01, 1e-3
    # The scale of the work: the elastic energy of the set-up bend.
    scale = 0.5 * kb * math.pi * rb ** 4 / 4 * a_setup ** 2
    # The trapezoid sum's error at this step: 1.3e-14 J a cycle (3e-8 of the
    # scale), and 5e-17 J at dt 1e-8 (second order); the switching law of
    # the spec did +2.15e-8 J.
    tolerance = 1e-6 * scale
    table = "P_lmp.txt" if a.kind == "lammps" else "P_lig.txt"
    failed = []
    for direction in (1, -1):
        run_dir = os.path.join(workdir, f"dir{direction}")
        os.makedirs(run_dir, exist_ok=True)
        shutil.copy(os.path.join(deck_runner.DECKS, "make_legs.py"), run_dir)
        rc, text = run_deck([a.engine], bend_deck(a.kind), run_dir, {"dt": dt, "dir": direction})
        if rc != 0:
            raise Failure(f"direction {direction}: exit {rc}:\n{text[-2000:]}")
        work = cycle_work(run_dir, table, dt)
        print(f"direction {direction}: " + ", ".join(f"{k} {v:+.4e} J" for k, v in work.items()))
        for tag in ("cycle2", "cycle3"):
            if not work.get(tag, math.inf) <= tolerance:
                failed.append(f"direction {direction}: the bond did {work.get(tag)} J of work on the driver "
                              f"in {tag} (a closed path at a fixed history; at most {tolerance:.3g} J)")
        if not work.get("cycle1", 0.0) < -tolerance:
            failed.append(f"direction {direction}: cycle1 grows the history and must dissipate: {work}")
    if failed:
        raise Failure("; ".join(failed))


def run(a):
    workdir = os.path.abspath(a.workdir)
    {"tetra": check_tetra, "bendcycle": check_bendcycle}[a.mode](a, workdir)


if __name__ == "__main__":
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True, choices=["tetra", "bendcycle"])
    p.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    p.add_argument("--engine", required=True)
    p.add_argument("--workdir", required=True)
    args = p.parse_args()
    main(lambda: run(args))
