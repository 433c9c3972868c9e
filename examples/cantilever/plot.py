"""Static deflection of the bonded-sphere cantilever (in.cantilever) against
Euler-Bernoulli and Timoshenko beam theory.

Usage: plot.py OUT_DIR   (holding final.txt and tip.txt from the deck)
Writes OUT_DIR/cantilever.png and prints the tip deflection, the two terms
of the theory and their ratio.

Beam equivalents of the bond (the deck's values; docs/models/bond-nonlinear.md):
  bending:  EI_eff     = k_tt I L_b     (bond moment k_tt I theta, theta = curvature L_b)
  shear:    kGA_eff    = k_ft A L_b     (bond shear force k_ft A s)
  w(x) = F x^2 (3L - x) / (6 EI_eff)  +  F x / kGA_eff      (clamped at x = 0)
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

R = 1.0e-3
LAMBDA = 1.0
K_TT = K_FT = 1.0e10      # the deck's kb
LOAD = 5.0e-5             # the deck's load (N)
LB = 2 * R


def read(path, skip_header):
    rows = []
    with open(path) as f:
        lines = f.readlines()[skip_header:]
    for line in lines:
        if line.strip() and not line.startswith("#"):
            rows.append([float(v) for v in line.split()])
    return rows


def main(out):
    rb = LAMBDA * R
    area = math.pi * rb ** 2
    inertia = math.pi * rb ** 4 / 4
    ei = K_TT * inertia * LB
    kga = K_FT * area * LB
    atoms = sorted(read(f"{out}/final.txt", 9), key=lambda r: r[0])
    x0 = atoms[0][1]
    xs = [a[1] - x0 for a in atoms]
    ws = [-a[3] for a in atoms]           # deflection, positive along the load
    span = (len(atoms) - 1) * LB

    def bending(x):
        return LOAD * x * x * (3 * span - x) / (6 * ei)

    def shear(x):
        return LOAD * x / kga

    tip = ws[-1]
    tip_b, tip_s = bending(span), shear(span)
    fine = [span * k / 400 for k in range(401)]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    ax.plot([x * 1e3 for x in fine], [bending(x) * 1e6 for x in fine], "-", color="0.6", lw=3,
            label="Euler-Bernoulli, $EI_{eff} = k_{tt} I L_b$")
    ax.plot([x * 1e3 for x in fine], [(bending(x) + shear(x)) * 1e6 for x in fine], "--", color="k", lw=1,
            label="+ shear (Timoshenko), $k_{ft} A L_b$")
    ax.plot([x * 1e3 for x in xs], [w * 1e6 for w in ws], "o", color="C3", ms=5, label="LIGGGHTS + granbond")
    ax.set_xlabel("x along the beam (mm)")
    ax.set_ylabel(r"deflection ($\mu$m)")
    ax.set_title(f"Cantilever, {len(atoms)} spheres, tip load {LOAD:g} N")
    ax.legend(loc="upper left")

    hist = read(f"{out}/tip.txt", 0)
    ax2.plot([r[0] * 5e-6 * 1e3 for r in hist], [-r[1] * 1e6 for r in hist], "-", color="C3", label="tip")
    ax2.axhline((tip_b + tip_s) * 1e6, color="k", ls="--", lw=1, label="theory (static)")
    ax2.set_xlabel("time (ms)")
    ax2.set_ylabel(r"tip deflection ($\mu$m)")
    ax2.set_title("settling (fix viscous)")
    ax2.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(f"{out}/cantilever.png", dpi=120)

    theory = tip_b + tip_s
    print(f"cantilever: tip deflection {tip:.6e} m; Euler-Bernoulli {tip_b:.6e} m + shear {tip_s:.3e} m "
          f"= {theory:.6e} m (bending term {tip_b / tip_s:.0f}x the shear term); "
          f"LIGGGHTS / theory = {tip / theory:.5f}")
    print(f"wrote {out}/cantilever.png")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
