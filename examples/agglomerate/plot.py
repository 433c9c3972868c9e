"""Plots of the agglomerate impact: bonds broken over time (by mode) and the
fragment size distribution. Usage: plot.py OUT_DIR (holding agglomerate.csv
and fragments.csv from the scene runner)."""

import csv
import sys
from collections import Counter
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main(out):
    out = Path(out)
    h = read(out / "agglomerate.csv")
    t_ms = [t * 1e3 for t in h["time"]]
    fig, ax = plt.subplots(figsize=(6, 4))
    for key, label in [
        ("broken_tension", "tension"),
        ("broken_compression", "compression"),
        ("broken_shear", "shear"),
    ]:
        ax.plot(t_ms, h[key], label=label)
    total = [a + b + c for a, b, c in zip(h["broken_tension"], h["broken_compression"], h["broken_shear"])]
    ax.plot(t_ms, total, "k--", label="all")
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("bonds broken")
    ax.set_title("Agglomerate impact: broken bonds by mode")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "broken_bonds.png", dpi=120)

    sizes = [int(s) for s in read(out / "fragments.csv")["size"]]
    counts = Counter(sizes)
    xs = sorted(counts)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog(xs, [counts[x] for x in xs], "o")
    ax.set_xlabel("fragment size (spheres)")
    ax.set_ylabel("number of fragments")
    ax.set_title(f"Fragment sizes ({len(sizes)} fragments, largest {max(sizes)})")
    fig.tight_layout()
    fig.savefig(out / "fragment_sizes.png", dpi=120)
    for name in ("broken_bonds.png", "fragment_sizes.png"):
        print(f"wrote {out / name}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "examples/agglomerate/out")
