"""The bonded disc hit by a bonded ball, BPM's bpm/rotational against
granbond's bond_style granbond with BPM's summed breakage rule: bonds broken
and kinetic energy against step, in one figure.

    python3 plot.py OUTDIR    (OUTDIR holds bpm.txt and granbond.txt: step broken ke)
writes OUTDIR/impact.png, copies it beside this script (the committed
figure) and prints the counts at a few steps.
"""
import os
import shutil
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

RUNS = (("bpm.txt", "BPM bond_style bpm/rotational", "tab:blue", "-"),
        ("granbond.txt", "granbond bond_style granbond, break bpm", "tab:red", "--"))


def read(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


def main(out):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    table = {}
    for name, label, colour, style in RUNS:
        rows = read(os.path.join(out, name))
        steps = [r[0] for r in rows]
        top.plot(steps, [r[1] for r in rows], style, color=colour, label=label)
        bottom.plot(steps, [r[2] * 1e3 for r in rows], style, color=colour, label=label)
        table[name] = {int(r[0]): r for r in rows}
    top.set_ylabel("bonds broken")
    bottom.set_ylabel("kinetic energy (mJ)")
    bottom.set_xlabel("step (1 us)")
    top.legend(loc="lower right")
    top.set_title("a bonded disc hit by a bonded ball at 7 m/s: BPM and granbond, same bonds and rule")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    png = os.path.join(out, "impact.png")
    fig.savefig(png, dpi=110)
    shutil.copy(png, os.path.join(os.path.dirname(os.path.abspath(__file__)), "impact.png"))
    print("step: broken and ke (mJ), BPM | granbond")
    for step in sorted(table["bpm.txt"]):
        if step % 1000 == 0 and step in table["granbond.txt"]:
            b, g = table["bpm.txt"][step], table["granbond.txt"][step]
            print(f"{step:6d}: {int(b[1]):4d} {b[2] * 1e3:.4f} | {int(g[1]):4d} {g[2] * 1e3:.4f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
