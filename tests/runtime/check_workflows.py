"""Engine-level checks that a workflow users run works or says why
(the testers' decks in decks/workflows/). One claim per mode:

  pour    LAMMPS: `fix pour` fills a box that holds no sphere when the run
          starts: pair granbond's contacts reach as far as the poured
          spheres need (their radius from fix pour, as pair granular
          takes it), so no atom is lost and no two spheres overlap by more
          than a few per cent of a diameter.

usage: check_workflows.py --mode MODE --kind lammps --engine BIN --workdir DIR
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, run_modes, run_ok  # noqa: E402

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


if __name__ == "__main__":
    run_modes(__doc__, {"pour": check_pour})
