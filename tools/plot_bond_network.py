#!/usr/bin/env python3
"""Draws the bond network that tools/bonds_to_vtk.py wrote, headless.

usage: plot_bond_network.py VTK_DIR --steps S1 S2 ... --field NAME --out PNG
                            [--view xz|xy|yz] [--title TEXT]

One panel per step (the nearest step in VTK_DIR/bonds.pvd): every intact
bond as a line between its centres, projected on the plane of --view and
coloured by the cell field NAME; with VTK_DIR/breaks.pvd, every bond broken
up to that step as a point at its centre, marked by mode. Reads the files
with bonds_to_vtk.read_vtp (strict), so a picture is also a check that
they parse.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bonds_to_vtk  # noqa: E402

AXES = {"xz": (0, 2), "xy": (0, 1), "yz": (1, 2)}
MARKERS = {1: ("distance", "s"), 2: ("tension", "^"), 3: ("compression", "v"), 4: ("shear", "x")}


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("vtk_dir")
    p.add_argument("--steps", type=int, nargs="+", required=True)
    p.add_argument("--field", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--view", default="xz", choices=sorted(AXES))
    p.add_argument("--title", default="")
    a = p.parse_args(argv)
    series = bonds_to_vtk.read_pvd(os.path.join(a.vtk_dir, "bonds.pvd"))
    breaks_pvd = os.path.join(a.vtk_dir, "breaks.pvd")
    breaks = dict(bonds_to_vtk.read_pvd(breaks_pvd)) if os.path.exists(breaks_pvd) else {}
    u, v = AXES[a.view]
    fig, axes = plt.subplots(1, len(a.steps), figsize=(4.2 * len(a.steps), 4.4), squeeze=False)
    polys = []
    for want in a.steps:
        step, name = min(series, key=lambda s: abs(s[0] - want))
        polys.append((step, bonds_to_vtk.read_vtp(os.path.join(a.vtk_dir, name)),
                      bonds_to_vtk.read_vtp(os.path.join(a.vtk_dir, breaks[step])) if step in breaks else None))
    values = [x for _, poly, _ in polys for x in poly["cells"].get(a.field, [])]
    if not values:
        print(f"plot_bond_network: no field {a.field} or no bonds in the chosen steps", file=sys.stderr)
        return 1
    lo, hi = min(values), max(values)
    if hi == lo:
        hi = lo + 1.0
    every = [pt for _, poly, _ in polys for pt in poly["points"]]
    pad = 0.05 * max(max(pt[u] for pt in every) - min(pt[u] for pt in every),
                     max(pt[v] for pt in every) - min(pt[v] for pt in every))
    box = (min(pt[u] for pt in every) - pad, max(pt[u] for pt in every) + pad,
           min(pt[v] for pt in every) - pad, max(pt[v] for pt in every) + pad)
    for ax, (step, poly, broken) in zip(axes[0], polys):
        segments = [[(poly["points"][i][u], poly["points"][i][v]), (poly["points"][j][u], poly["points"][j][v])]
                    for i, j in poly["lines"]]
        lines = LineCollection(segments, cmap="viridis", linewidths=0.8)
        lines.set_array(poly["cells"][a.field])
        lines.set_clim(lo, hi)
        ax.add_collection(lines)
        if broken is not None:
            for mode, (label, marker) in MARKERS.items():
                pts = [pt for pt, m in zip(broken["points"], broken["points_data"]["mode"]) if m == mode]
                if pts:
                    ax.scatter([pt[u] for pt in pts], [pt[v] for pt in pts], s=6, marker=marker, alpha=0.5,
                               label=f"broken, {label} ({len(pts)})")
            if any(broken["points_data"]["mode"]):
                ax.legend(loc="upper right", fontsize=7)
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
        ax.set_aspect("equal")
        ax.set_title(f"step {step}: {len(poly['lines'])} intact bonds", fontsize=9)
        ax.set_xlabel(f"{a.view[0]} (m)")
        ax.set_ylabel(f"{a.view[1]} (m)")
    fig.colorbar(lines, ax=axes[0].tolist(), label=a.field, shrink=0.8)
    if a.title:
        fig.suptitle(a.title, fontsize=10)
    fig.savefig(a.out, dpi=110)
    print(f"plot_bond_network: {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
