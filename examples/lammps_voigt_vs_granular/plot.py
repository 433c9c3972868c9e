"""granbond voigt against pair granular on the oblique collision:
velocities and spins of both spheres over time, and the lever-arm
difference (torque lever R in granbond, R - delta/2 in pair granular).

    python3 plot.py OUTDIR    (OUTDIR holds granbond.txt and granular.txt)
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

DT = 1e-6          # s, the deck's time step
RADIUS = 1e-3      # m


def read(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(c) for c in line.split()])
    return rows


def main(out):
    ours = read(os.path.join(out, "granbond.txt"))
    theirs = read(os.path.join(out, "granular.txt"))
    n = min(len(ours), len(theirs))
    ours, theirs = ours[:n], theirs[:n]
    t = [r[0] * DT * 1e6 for r in ours]   # us
    overlap = [2 * RADIUS - math.dist(r[1:4], r[4:7]) for r in ours]
    delta_max = max(overlap)
    touching = [s for s, d in zip(t, overlap) if d > 0]

    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    series = (("v1x", 7, "sphere 1"), ("v1y", 8, "sphere 1"), ("v2x", 10, "sphere 2"), ("v2y", 11, "sphere 2"))
    ax = axes[0][0]
    for name, col, who in series:
        ax.plot(t, [r[col] for r in ours], "-", lw=2, label=f"{name} granbond")
        ax.plot(t, [r[col] for r in theirs], "--", lw=1.2, color="k", label=f"{name} granular" if col == 7 else None)
    ax.set_ylabel("velocity (m/s)")
    ax.set_title("velocities (dashed: pair granular)")
    ax.legend(fontsize=7, ncol=2)

    ax = axes[0][1]
    ax.plot(t, [r[15] for r in ours], "-", lw=2, label="w1z granbond")
    ax.plot(t, [r[15] for r in theirs], "--", color="k", label="w1z granular")
    ax.plot(t, [r[18] for r in ours], "-", lw=2, alpha=0.6, label="w2z granbond")
    ax.set_ylabel("spin (rad/s)")
    ax.set_title("spins about z (w1z = w2z here)")
    ax.legend(fontsize=8)

    ax = axes[1][0]
    ax.plot(t, [d * 1e6 for d in overlap], "-")
    ax.set_ylabel("overlap delta (um)")
    ax.set_xlabel("time (us)")
    ax.set_title(f"overlap: delta_max = {delta_max * 1e6:.3g} um, delta_max/(2R) = {delta_max / (2 * RADIUS):.2%}")

    ax = axes[1][1]
    dw = [abs(a[15] - b[15]) for a, b in zip(ours, theirs)]
    wscale = max(abs(b[15]) for b in theirs)
    ax.plot(t, [d / wscale for d in dw], "-", label="|w1z granbond - granular| / max|w1z|")
    dv = [max(abs(p - q) for p, q in zip(a[7:13], b[7:13])) for a, b in zip(ours, theirs)]
    vscale = max(abs(c) for b in theirs for c in b[7:13])
    ax.plot(t, [d / vscale for d in dv], "-", label="max |v granbond - granular| / max|v|")
    ax.axhline(delta_max / (2 * RADIUS), color="r", ls=":", label="delta_max / (2R): lever-arm bound")
    ax.set_xlabel("time (us)")
    ax.set_title("relative difference")
    ax.legend(fontsize=8)
    for row in axes:
        for a in row:
            if touching:
                a.axvspan(touching[0], touching[-1], color="0.9", zorder=0)
    fig.suptitle("Oblique collision, granbond voigt (torque lever R) vs pair granular (lever R - delta/2); grey: in contact")
    fig.tight_layout()
    png = os.path.join(out, "voigt_vs_granular.png")
    fig.savefig(png, dpi=120)
    print(f"delta_max = {delta_max:.4g} m, delta_max/(2R) = {delta_max / (2 * RADIUS):.3g}")
    print(f"final w1z: granbond {ours[-1][15]:.6g} rad/s, granular {theirs[-1][15]:.6g} rad/s "
          f"(relative {abs(ours[-1][15] - theirs[-1][15]) / abs(theirs[-1][15]):.3g})")
    print(f"worst relative velocity difference {max(dv) / vscale:.3g}")
    print(f"wrote {png}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
