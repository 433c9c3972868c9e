"""Angle of repose of the heap (in.heap), voigt vs the built-in
hooke/stiffness + tangential history (+ rolling_friction epsd2), with and
without rolling resistance.

Usage: plot.py OUT_DIR   (holding <case>/final.txt for the cases run.sh runs)
Writes OUT_DIR/heap.png (surface profiles and angles) and OUT_DIR/angles.csv.

Angle of repose (geometry only): the heap surface h(r) is the highest sphere
top z + R in each 2 mm ring around the axis; a straight line is fitted to
the flank (rings whose h lies between 20 % and 80 % of the heap height);
angle = atan(-slope).
"""

import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

CASES = [
    ("voigt_rolling", "voigt + rolling_friction voigt", "C3", "-"),
    ("stock_epsd2", "hooke/stiffness + history + epsd2", "k", "--"),
    ("voigt", "voigt, no rolling resistance", "C0", "-"),
    ("stock", "hooke/stiffness + history, no rolling", "0.4", "--"),
]
RING = 2.0e-3


def read_final(path):
    with open(path) as f:
        lines = f.readlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    data = np.array([[float(v) for v in line.split()] for line in lines[start + 1:] if line.strip()])
    return {c: data[:, k] for k, c in enumerate(cols)}


def profile(atoms):
    r = np.hypot(atoms["x"], atoms["y"])
    top = atoms["z"] + atoms["radius"]
    rings = np.floor(r / RING).astype(int)
    centres, heights = [], []
    for k in range(rings.max() + 1):
        sel = rings == k
        if sel.any():
            centres.append((k + 0.5) * RING)
            heights.append(top[sel].max())
    return np.array(centres), np.array(heights)


def angle(centres, heights):
    hmax = heights.max()
    peak = int(np.argmax(heights))
    sel = np.zeros(len(heights), bool)
    sel[peak:] = (heights[peak:] > 0.2 * hmax) & (heights[peak:] < 0.8 * hmax)
    if sel.sum() < 2:
        return float("nan"), None
    slope, icpt = np.polyfit(centres[sel], heights[sel], 1)
    return math.degrees(math.atan(-slope)), (centres[sel], slope, icpt)


def main(out):
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.4), gridspec_kw={"width_ratios": [3, 2]})
    results = []
    for name, label, colour, style in CASES:
        path = os.path.join(out, name, "final.txt")
        if not os.path.exists(path):
            continue
        atoms = read_final(path)
        c, h = profile(atoms)
        a, fit = angle(c, h)
        results.append((name, label, a, h.max(), len(atoms["x"])))
        ax.plot(c * 1e3, h * 1e3, style, color=colour, label=f"{label}: {a:.1f} deg")
        if fit:
            xs, slope, icpt = fit
            ax.plot(xs * 1e3, (icpt + slope * xs) * 1e3, ":", color=colour, lw=2.5)
    ax.set_xlabel("distance from the axis r (mm)")
    ax.set_ylabel("heap surface height (mm)")
    ax.set_title("Heap profiles (dotted: flank fit)")
    ax.set_xlim(0, 60)
    ax.legend(fontsize=8)
    names = [r[0] for r in results]
    ax2.bar(range(len(results)), [r[2] for r in results],
            color=[next(c for n, _, c, _ in CASES if n == name) for name in names])
    ax2.set_xticks(range(len(results)))
    ax2.set_xticklabels([n.replace("_", "\n") for n in names], fontsize=8)
    ax2.set_ylabel("angle of repose (deg)")
    ax2.set_title("voigt vs built-in, with / without rolling")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "heap.png"), dpi=120)
    with open(os.path.join(out, "angles.csv"), "w") as f:
        f.write("case,angle_deg,height_m,spheres\n")
        for name, _, a, hm, n in results:
            f.write(f"{name},{a:.3f},{hm:.6e},{n}\n")
    for name, label, a, hm, n in results:
        print(f"heap: {name:14s} angle of repose {a:5.1f} deg, height {hm * 1e3:5.1f} mm ({n} spheres; {label})")
    print(f"wrote {os.path.join(out, 'heap.png')}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
