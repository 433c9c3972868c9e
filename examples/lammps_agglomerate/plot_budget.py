#!/usr/bin/env python3
"""The bonds' energy budget of the LAMMPS agglomerate impact over time
(energy.txt of in.lammps_agglomerate, written by run.sh): kinetic energy
(translation, rotation), the energy the bonds store, and what they
dissipated by damping and by hysteresis and released by breaking, stacked;
the rest of the first output's total is what the contacts and the wall
hold or dissipated, which the bonds' budget does not count.

usage: plot_budget.py energy.txt budget.png [TITLE]
(examples/agglomerate_liggghts/plot.py draws LIGGGHTS's with its own title)
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(source, target, title="LAMMPS pair granbond: the bonds' energy budget, ball into a wall at 3 m/s"):
    rows = [list(map(float, line.split())) for line in open(source) if line.strip() and not line.startswith("#")]
    time = [r[1] * 1e3 for r in rows]
    names = ["kinetic (translation)", "kinetic (rotation)", "stored in bonds", "dissipated by damping",
             "dissipated by hysteresis", "released by breaks"]
    terms = [[r[2 + k] * 1e3 for r in rows] for k in range(6)]
    start = sum(t[0] for t in terms)
    rest = [start - sum(t[i] for t in terms) for i in range(len(rows))]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.stackplot(time, *terms, rest, labels=names + ["contacts and wall (not the bonds')"],
                 colors=["#4c72b0", "#8fb0e0", "#55a868", "#c44e52", "#dd8452", "#8172b3", "#cccccc"])
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("energy (mJ)")
    ax.set_xlim(time[0], time[-1])
    ax.set_title(title)
    ax.legend(loc="lower left", fontsize=8)
    fig.tight_layout()
    fig.savefig(target, dpi=120)
    last = rows[-1]
    print(f"start {start:.4g} mJ; at {time[-1]:.3g} ms: kinetic {terms[0][-1] + terms[1][-1]:.4g}, stored "
          f"{terms[2][-1]:.4g}, damping {terms[3][-1]:.4g}, hysteresis {terms[4][-1]:.4g}, released "
          f"{terms[5][-1]:.4g}, contacts and wall {rest[-1]:.4g} mJ (step {last[0]:.0f})")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
