#!/usr/bin/env python3
"""`compute pair/gran/local/bond` without keywords writes LIGGGHTS-INL's
columns: 1-6 both centres, 7-8 both ids, 9 the periodic flag, 10-12 the
force on atom id_i, 13-15 and 16-18 its parts along and across the centre
line, 19-21 the torque on id_i, 22-24 and 25-27 its parts, then the pair's
history. Checked on the spin deck of tests/validation/inl (two bonded
spheres, sphere 1 frozen): the force on sphere 2 that `fix print` writes is
the bond's, so the row's force is it (or its negative, seen from sphere 1),
and the parts add up to the force and torque and lie along and across
the line between the centres.

    check_inl_layout.py --liggghts BIN --workdir DIR
"""

import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from deck_runner import Failure, main, read_dump, run_deck  # noqa: E402
import deck_runner  # noqa: E402

DECK = os.path.join(HERE, "..", "validation", "inl", "spin_twist_bend", "in.spin")
EVERY = 500


def deck_text():
    with open(DECK, encoding="utf-8") as f:
        text = f.read()
    out = []
    for line in text.splitlines():
        if line.startswith("fix out all print"):
            out.append(line.replace("print 50", f"print {EVERY}"))
            out.append("compute bl all pair/gran/local/bond")
            columns = " ".join(f"c_bl[{c}]" for c in range(1, 28))
            out.append(f"dump bonds all local {EVERY} bonds.dump {columns}")
            out.append("dump_modify bonds format \"" + " ".join(["%.17g"] * 27) + "\"")
            continue
        out.append(line)
    return "\n".join(out) + "\n"


def close(a, b, scale):
    return abs(a - b) <= 1e-9 * max(scale, 1e-300)


def check(args):
    workdir = args.workdir
    os.makedirs(workdir, exist_ok=True)
    with open(os.path.join(workdir, "in.layout"), "w", encoding="utf-8") as f:
        f.write(deck_text())
    deck_runner.DECKS = workdir
    rc, text = run_deck([args.liggghts], "in.layout", workdir)
    if rc != 0:
        raise Failure(f"the deck exited with {rc}:\n{text[-3000:]}")
    dump = read_dump(os.path.join(workdir, "bonds.dump"))
    with open(os.path.join(workdir, "spin.txt"), encoding="utf-8") as f:
        table = [[float(v) for v in line.split()] for line in f.read().splitlines()[1:] if line.strip()]
    header = "ITEM: ENTRIES " + " ".join(f"c_bl[{c}]" for c in range(1, 28))
    with open(os.path.join(workdir, "bonds.dump"), encoding="utf-8") as f:
        if header not in f.read():
            raise Failure("the dump does not hold 27 columns")
    checked = 0
    dt = 1e-7
    for row_t in table:
        step = round(row_t[0] / dt)
        if step not in dump or step == 0:
            continue
        rows = dump[step]
        if len(rows) != 1:
            raise Failure(f"step {step}: {len(rows)} rows, one bond")
        r = rows[0]
        if sorted(r[6:8]) != [1.0, 2.0] or r[8] != 0.0:
            raise Failure(f"step {step}: ids {r[6:8]}, periodic flag {r[8]}")
        x2 = row_t[1:4]
        centres = {1.0: [0.0, 0.0, 0.0], 2.0: x2}
        if any(not close(r[c], centres[r[6]][c], 1e-3) or not close(r[3 + c], centres[r[7]][c], 1e-3)
               for c in range(3)):
            raise Failure(f"step {step}: centres {r[0:6]}, sphere 2 at {x2}")
        sign = 1.0 if r[6] == 2.0 else -1.0
        f2 = [sign * v for v in row_t[10:13]]
        scale = max(abs(v) for v in f2)
        force, fn, ft = r[9:12], r[12:15], r[15:18]
        torque, tn, tt = r[18:21], r[21:24], r[24:27]
        if any(not close(force[c], f2[c], scale) for c in range(3)):
            raise Failure(f"step {step}: force {force} on atom {r[6]:.0f}, fix print {f2}")
        line = [r[c] - r[3 + c] for c in range(3)]
        length = math.sqrt(sum(v * v for v in line))
        n = [v / length for v in line]
        for what, whole, along, across in (("force", force, fn, ft), ("torque", torque, tn, tt)):
            s = max(max(abs(v) for v in whole), 1e-300)
            if any(not close(along[c] + across[c], whole[c], s) for c in range(3)):
                raise Failure(f"step {step}: {what} parts {along} + {across} != {whole}")
            cross = [along[1] * n[2] - along[2] * n[1], along[2] * n[0] - along[0] * n[2],
                     along[0] * n[1] - along[1] * n[0]]
            if any(abs(v) > 1e-9 * s for v in cross) or abs(sum(a * b for a, b in zip(across, n))) > 1e-9 * s:
                raise Failure(f"step {step}: {what} parts not along and across the line {n}")
        checked += 1
    if checked < 10:
        raise Failure(f"only {checked} steps to compare")
    print(f"ok: {checked} steps: ids, centres, force on id_i as fix print has it, parts along and across n")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--liggghts", required=True)
    ap.add_argument("--workdir", required=True)
    parsed = ap.parse_args()
    main(lambda: check(parsed))
