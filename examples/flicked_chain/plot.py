"""The flicked chain (in.flicked_chain, in.flicked_chain_lammps): the top
sphere's sideways position against time in both history modes, LIGGGHTS and
LAMMPS overlaid, and each bond's bending angle against the residual angle
the law predicts for a kept history, (1 - k/ku) times the extreme of the
side it ends on.

usage: plot.py OUT_DIR   (the folder run.sh writes: liggghts_no, lammps_yes, ...)
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chain_analysis import DT, load_chain, load_bond_angles, residual_summary  # noqa: E402


def main(out):
    fig, axes = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    styles = {"liggghts": ("-", 1.6), "lammps": ("--", 1.0)}
    labels = {"off": "history kept (historyReset off, the default)", "on": "historyReset on"}
    for ax, reset in zip(axes, ("off", "on")):
        for engine in ("liggghts", "lammps"):
            path = os.path.join(out, f"{engine}_{reset}", "chain.txt")
            if not os.path.exists(path):
                continue
            rows = load_chain(path)
            t = [r[0] * DT * 1e3 for r in rows]
            x = [r[13] * 1e6 for r in rows]
            ls, lw = styles[engine]
            ax.plot(t, x, ls, lw=lw, label=f"{engine.upper() if engine == 'lammps' else 'LIGGGHTS'}")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_ylabel("top sphere x (um)")
        ax.set_title(labels[reset])
        ax.legend(loc="upper right")
    axes[-1].set_xlabel("time (ms)")
    bonds = os.path.join(out, "liggghts_off", "bond_angles.txt")
    if os.path.exists(bonds):
        lines = residual_summary(load_bond_angles(bonds))
        axes[0].text(0.01, 0.03, "\n".join(lines), transform=axes[0].transAxes, fontsize=7,
                     family="monospace", va="bottom")
    fig.suptitle("Five bonded spheres, bottom held, top flicked sideways; ku = 2k, no damping")
    fig.tight_layout()
    png = os.path.join(out, "flicked_chain.png")
    fig.savefig(png, dpi=120)
    print(f"plot: {png}")


if __name__ == "__main__":
    main(sys.argv[1])
