"""Force-displacement loop of the two-sphere cycle (in.bond_cycle) over the
six-branch normal law (docs/models/bond-nonlinear.md, eq. 6).

Usage: plot.py OUT_DIR   (holding cycle.txt from the deck)
Writes OUT_DIR/bond_cycle.png and prints the largest deviation between
LIGGGHTS and the spec's law along the same path.

The analytic curve is computed here, independently of the engine and of the
Rust core, from the spec's table: history dmax = max(d, dmax), dmin =
min(d, dmin) updated before the law, then the branch that contains d.
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

# the deck's values
R = 1.0e-3
LAMBDA = 0.5
K1, KU1, KC1 = 1.0e9, 2.0e9, 5.0e8     # compression (N/m^2.5)
K2, KU2, KC2 = 1.0e11, 2.0e11, 5.0e10   # tension (N/m^3)
A = math.pi * (LAMBDA * R) ** 2


def spec_force(d, dmax, dmin):
    """Fn(d) of the spec's table (> 0 repulsive), given updated history."""
    dc1 = ((KU1 - K1) / (KU1 + KC1)) ** 2 * dmax
    dc2 = (KU2 - K2) / (KU2 + KC2) * dmin
    if d < dmin:
        return K2 * A * d
    if d < dc2:
        return KU2 * A * d + (K2 - KU2) * A * dmin
    if d < 0:
        return -KC2 * A * d
    if d < dc1:
        return -KC1 * A * math.sqrt(abs(d))
    if d < dmax:
        return KU1 * A * math.sqrt(abs(d)) + (K1 - KU1) * A * math.sqrt(dmax)
    return K1 * A * math.sqrt(abs(d))


def spec_path(ds):
    dmax = dmin = 0.0
    out = []
    for d in ds:
        dmax, dmin = max(d, dmax), min(d, dmin)
        out.append(spec_force(d, dmax, dmin))
    return out


def main(out):
    rows = []
    with open(f"{out}/cycle.txt") as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    rows.sort(key=lambda r: r[0])
    # bond created at step 1 with r0 = r then (sphere 1 fixed at x1)
    r0 = rows[0][2] - rows[0][1]
    d = [r0 - (x2 - x1) for _, x1, x2, _ in rows]
    f_engine = [f2x for *_, f2x in rows]   # on sphere 2 (+x side): > 0 repels
    f_spec = spec_path(d)

    # the analytic curve on a fine path through the same turning points
    turns, turn_steps = [0.0], []
    for k in range(1, len(d) - 1):
        if (d[k] - d[k - 1]) * (d[k + 1] - d[k]) < 0:
            turns.append(d[k])
            turn_steps.append(k)
    turns.append(d[-1])
    fine = []
    for a, b in zip(turns, turns[1:]):
        n = 2000
        fine += [a + (b - a) * k / n for k in range(n)]
    fine_f = spec_path(fine)

    scale = max(abs(v) for v in f_spec)
    err = max(abs(a - b) for a, b in zip(f_engine, f_spec)) / scale

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    ax.plot([v * 1e6 for v in fine], fine_f, "-", color="0.6", lw=4, label="spec: six-branch law (analytic)")
    ax.plot([v * 1e6 for v in d], f_engine, "-", color="C3", lw=1.2, label="LIGGGHTS + granbond")
    for n, k in enumerate(turn_steps, 1):
        ax.annotate(f"turn {n}", (d[k] * 1e6, f_engine[k]), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.axhline(0, color="k", lw=0.5)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel(r"$\delta = r_0 - r$ ($\mu$m; > 0 compression)")
    ax.set_ylabel(r"normal force $F_n$ (N; > 0 repulsive)")
    ax.set_title(f"Bond load/unload/reload cycle (max deviation {err:.1e} of max |F|)")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(f"{out}/bond_cycle.png", dpi=120)
    print(f"bond_cycle: {len(d)} steps, turning points (um): "
          + ", ".join(f"{t * 1e6:.1f}" for t in turns[1:-1])
          + f"; max |F_engine - F_spec| / max |F| = {err:.2e}")
    print(f"wrote {out}/bond_cycle.png")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
