#!/usr/bin/env python3
"""Draws the scale study of bench/scale.sh.

    python3 bench/plot_scale.py [CSV] [PNG]

CSV defaults to docs/figures/data/perf_scale.csv, PNG to
docs/figures/perf_scale.png. Left: ns per bond-step against the number of
bonds, LIGGGHTS and LAMMPS, 1 and 2 MPI ranks (log x). Right: memory per
bond, (max RSS with bonds - without) / bonds on 1 rank, with the slope of a
least-squares line through the bonded RSS against bonds (the fixed part of
the process drops out). Also prints the slope, the spread of the cost
(largest / smallest ns per bond-step, 1 rank) and the 2-rank speed-ups.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "docs/figures/data/perf_scale.csv")
dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs/figures/perf_scale.png")

with open(src) as f:
    rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
if not rows:
    sys.exit(f"plot_scale.py: no rows in {src}")


def series(engine, ranks, key):
    pts = [(int(r["bonds"]), float(r[key])) for r in rows
           if r["engine"] == engine and int(r["ranks"]) == ranks and r[key] not in ("", "nan")]
    return [p[0] for p in sorted(pts)], [p[1] for p in sorted(pts)]


def slope(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.6))
style = {"liggghts": ("C0", "LIGGGHTS (liggghts-granbond)"), "lammps": ("C1", "LAMMPS 2021 (lmp-granbond)")}
for engine, (color, label) in style.items():
    for ranks, ls, marker in ((1, "-", "o"), (2, "--", "s")):
        x, y = series(engine, ranks, "ns_per_bond_step")
        if x:
            ax1.plot(x, y, ls, color=color, marker=marker, label=f"{label}, {ranks} rank{'s' if ranks > 1 else ''}")
    x, y = series(engine, 1, "bytes_per_bond")
    if x:
        ax2.plot(x, y, "-o", color=color, label=f"{engine}: (RSS bonds - no bonds) / bonds")
    x, rss = series(engine, 1, "maxrss_bonds_kb")
    if len(x) >= 2:
        big = [(b, r) for b, r in zip(x, rss) if b >= 1e4] or list(zip(x, rss))
        s = slope([b for b, _ in big], [r * 1024.0 for _, r in big])
        ax2.axhline(s, color=color, ls=":", label=f"{engine}: slope of bonded RSS (atoms included), >= 1e4 bonds: {s:.0f} B")
        print(f"{engine}: RSS slope {s:.0f} bytes per bond (sizes >= 1e4 bonds)")
    x, y = series(engine, 1, "ns_per_bond_step")
    if y:
        print(f"{engine}: 1 rank ns/bond-step {min(y):.1f} .. {max(y):.1f}, largest/smallest {max(y) / min(y):.2f}")
    x, sp = series(engine, 2, "speedup_vs_1rank")
    if sp:
        print(f"{engine}: 2-rank speed-up " + ", ".join(f"{b}: {v:.2f}" for b, v in zip(x, sp)))

ax1.set_xscale("log")
ax1.set_xlabel("bonds")
ax1.set_ylabel("ns per bond-step (wall clock)")
ax1.set_title("(loop with bonds - without) / (bonds x steps)")
ax1.set_ylim(bottom=0)
ax1.grid(True, which="both", alpha=0.3)
ax1.legend(fontsize=7)
ax2.set_xscale("log")
ax2.set_xlabel("bonds")
ax2.set_yscale("log")
ax2.set_ylabel("bytes per bond (max RSS, 1 rank)")
ax2.set_title("memory per bond (small blocks: allocation granularity)", fontsize=10)
ax2.grid(True, which="both", alpha=0.3)
ax2.legend(fontsize=6.5, loc="upper right")
with open(src) as f:
    note = f.readline().lstrip("# ").strip()
fig.suptitle(f"granbond bonded blocks, 2-core machine ({note.split(',')[1].strip() if ',' in note else ''})", fontsize=9)
fig.tight_layout()
os.makedirs(os.path.dirname(dst), exist_ok=True)
fig.savefig(dst, dpi=110)
print(f"plot_scale.py: wrote {dst}")
