"""Engine-level checks that a workflow users run works or says why
(the testers' decks in decks/workflows/). One claim per mode:

  pour    LAMMPS: `fix pour` fills a box that holds no sphere when the run
          starts: pair granbond's contacts reach as far as the poured
          spheres need (their radius from fix pour, as pair granular
          takes it), so no atom is lost and no two spheres overlap by more
          than a few per cent of a diameter.
  thin2d  LAMMPS or LIGGGHTS: a 2d run (dimension 2) has no images in z,
          so a bonded plate in a box as thin in z as its spheres runs and
          forms and breaks the same bonds as in a box 250 times thicker.
  deform  LAMMPS: a periodic box that fix deform shrinks below twice the
          neighbour reach during a run stops it at that step with an ERROR
          naming the box change; the same run with the box kept at its
          size keeps its one bond.
  smooth  LAMMPS: smooth bond damping's default velocities are physical
          quantities: a twisted pair spins down alike (to round-off) in
          units si, cgs, micro and nano; in units lj, which has no physical
          scale, the run stops with an ERROR naming smooth_velocity unless
          the deck gives the velocities.
  minimize LAMMPS: a minimizer with a line search (cg), whose rejected
          trial passes would advance the bonds, is refused with an ERROR
          naming it; a damped-dynamics minimizer (fire) runs on a bonded
          block without losing an atom or a bond and says how the bonds
          are stepped.
  createstep LAMMPS: a block to be bonded at step 1, then `reset_timestep
          2000` and a run: the run warns that create_step 1 is not after
          its start, also when `run 0` or `write_data` came first.

usage: check_workflows.py --mode MODE --kind lammps|liggghts --engine BIN --workdir DIR
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, run_deck, run_modes, run_ok, thermo_blocks  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks", "workflows")


def closest(path):
    """Sphere count and the closest pair of centres, in sums of radii, of a
    dump (id x y z radius) in a box periodic in x and y."""
    lines = open(path, encoding="utf-8").read().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("ITEM: BOX BOUNDS"))
    box = [[float(v) for v in lines[k + 1 + d].split()[:2]] for d in range(3)]
    lx, ly = box[0][1] - box[0][0], box[1][1] - box[1][0]
    a = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    rows = [[float(x) for x in line.split()] for line in lines[a + 1:] if line.strip()]
    best = float("inf")
    for i, p in enumerate(rows):
        for q in rows[i + 1:]:
            dx, dy, dz = p[1] - q[1], p[2] - q[2], p[3] - q[3]
            dx -= lx * round(dx / lx)
            dy -= ly * round(dy / ly)
            best = min(best, (dx * dx + dy * dy + dz * dz) ** 0.5 / (p[4] + q[4]))
    return len(rows), best


def check_pour(a, workdir):
    run_ok([a.engine], "pour_empty_box.in", workdir, {"style": "granbond"})
    count, best = closest(os.path.join(workdir, "final.txt"))
    if count != 100 or best < 0.95:
        raise Failure(f"poured into an empty box: {count} spheres of 100, closest centres {best:.3f} diameters apart")
    print(f"ok: poured into an empty box: {count} spheres, closest centres {best:.3f} diameters apart")


def thermo_of(text, columns):
    """The rows of the thermo blocks of `columns` columns."""
    return [row for header, rows in thermo_blocks(text) if len(header) == columns for _, row in rows]


def last_thermo(text, columns):
    """The last thermo row of `columns` columns, as floats."""
    rows = thermo_of(text, columns)
    if not rows:
        raise Failure(f"no thermo rows of {columns} columns in:\n{text[-2000:]}")
    return rows[-1]


def thermo_at(text, columns, step):
    """The first thermo row of `columns` columns at `step`."""
    for row in thermo_of(text, columns):
        if row[0] == step:
            return row
    raise Failure(f"no thermo row at step {step}")


def check_thin2d(a, workdir):
    if a.kind == "lammps":
        deck, thin, thick = "plate_2d_lammps.in", {"zhalf": 0.001}, {"zhalf": 0.25}
    else:
        deck, thin, thick = "plate_2d_liggghts.in", {"zlo": -0.001, "zhi": 0.001}, {"zlo": -0.25, "zhi": 0.25}
    counts = []
    for label, variables in (("thin", thin), ("thick", thick)):
        text = run_ok([a.engine], deck, os.path.join(workdir, label), variables)
        counts.append(last_thermo(text, 5)[2:5])
    if counts[0] != counts[1] or counts[0][0] < 100:
        raise Failure(f"2d plate, created/broken/intact: thin box {counts[0]}, thick box {counts[1]}")
    print(f"ok: a 2d plate in a box 2 mm thin in z runs as in a 0.5 m one: created/broken/intact {counts[0]}")


def check_deform(a, workdir):
    rc, text = run_deck([a.engine], "deform_shrinks_box.in", os.path.join(workdir, "shrink"), {"final": 4.2e-3})
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    if rc == 0 or not any("as the box changed" in line and "fix deform" in line for line in errors):
        raise Failure(f"a box shrunk below twice the reach during a run: exit {rc}, errors {errors or text[-1500:]}")
    print(f"ok: shrunk below twice the reach: {errors[0]}")
    text = run_ok([a.engine], "deform_shrinks_box.in", os.path.join(workdir, "kept"), {"final": 6e-3})
    created, broken, intact = last_thermo(text, 7)[2:5]
    if (created, broken, intact) != (1, 0, 1):
        raise Failure(f"the box kept its size: created/broken/intact {created, broken, intact}, not 1 0 1")
    print("ok: the box kept its size: its bond stays intact")


def spins(text):
    """The `SPIN step w2` lines of smooth_damping_units.in (screen and log
    both hold them), as w2 values in step order."""
    by_step = {int(w[1]): float(w[2]) for w in (line.split() for line in text.splitlines()) if w[:1] == ["SPIN"]}
    return [by_step[k] for k in sorted(by_step)]


def check_smooth(a, workdir):
    runs = {}
    for style in ("si", "cgs", "micro", "nano"):
        runs[style] = spins(run_ok([a.engine], "smooth_damping_units.in", os.path.join(workdir, style), {"style": style}))
    reference = runs["si"]
    if len(reference) != 7 or abs(reference[-1]) >= 0.9 * reference[0]:
        raise Failure(f"si: the damped spin {reference} (7 values, damped below 0.9 of the start expected)")
    for style, w in runs.items():
        worst = max(abs(x - y) / abs(y) for x, y in zip(w, reference)) if len(w) == len(reference) else float("inf")
        if worst > 1e-9:
            raise Failure(f"units {style}: spin {w} against si {reference} (relative {worst:.2e})")
        print(f"ok: units {style}: the spin follows si's to {worst:.1e}")
    rc, text = run_deck([a.engine], "smooth_damping_units.in", os.path.join(workdir, "lj"), {"style": "lj"})
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    if rc == 0 or not any("smooth_velocity" in line for line in errors):
        raise Failure(f"units lj without smoothing velocities: exit {rc}, errors {errors or text[-1500:]}")
    print(f"ok: units lj: {errors[0]}")
    w = spins(run_ok([a.engine], "smooth_damping_units.in", os.path.join(workdir, "lj_given"),
                     {"style": "lj", "explicit": "yes"}))
    if w != reference:
        raise Failure(f"units lj with the velocities given: spin {w} against si {reference}")
    print("ok: units lj with the velocities given: the spin is si's")


def check_minimize(a, workdir):
    rc, text = run_deck([a.engine], "minimize_bonds.in", os.path.join(workdir, "cg"), {"minstyle": "cg"})
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    if rc == 0 or not any("min_style cg" in line and "line search" in line for line in errors):
        raise Failure(f"minimize with cg: exit {rc}, errors {errors or text[-1500:]}")
    print(f"ok: cg: {errors[0]}")
    text = run_ok([a.engine], "minimize_bonds.in", os.path.join(workdir, "fire"), {"minstyle": "fire"})
    if "min_style fire steps the contacts' and bonds' history" not in text:
        raise Failure("minimize with fire: the log does not say how the bonds are stepped")
    before = thermo_at(text, 6, 1000)
    after = last_thermo(text, 6)
    if after[1] != 120 or after[3:6] != before[3:6] or not after[2] < 0.5 * before[2]:
        raise Failure(f"minimize with fire: step atoms fnorm created broken intact {before} -> {after}")
    print(f"ok: fire: 120 atoms, created/broken/intact {after[3:6]} kept, fnorm {before[2]:g} -> {after[2]:g}")


def check_createstep(a, workdir):
    for pre in ("none", "run0", "writedata"):
        text = run_ok([a.engine], "create_step_reset.in", os.path.join(workdir, pre), {"pre": pre})
        warned = [line for line in text.splitlines() if line.startswith("WARNING") and "create_step 1" in line]
        created = last_thermo(text, 4)[1]
        if not warned or "2000" not in warned[0] or created != 0:
            raise Failure(f"pre {pre}: {created:g} bonds created, create_step warnings {warned}")
        print(f"ok: pre {pre}: {warned[0][:150]}")


if __name__ == "__main__":
    run_modes(__doc__, {"pour": check_pour, "thin2d": check_thin2d, "deform": check_deform, "smooth": check_smooth,
                         "minimize": check_minimize, "createstep": check_createstep})
