#!/usr/bin/env python3
"""Figures of docs/speed-accuracy.md from the CSV files of the study.

    python3 docs/plots.py CSV_DIR FIG_DIR

CSV_DIR is what `cargo run --release -p granbond-scene --example study -- CSV_DIR` wrote.
One PNG per figure in FIG_DIR; docs/make-figures.sh runs both steps.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return [dict(zip(header, map(float, r))) for r in body]


def names(csv_dir):
    out = {}
    with open(os.path.join(csv_dir, "names.txt")) as f:
        for line in f:
            key, value = line.split(": ", 1)
            out[key] = value.strip().split("|")
    return out


def finite(x):
    return x == x and not math.isinf(x)


TITLES = {
    "tension": "Linear tension oscillator: period error",
    "sqrt": "Square-root compression oscillator (amplitude 0.04 rb): period error",
    "cantilever": "Cantilever, 6 bonds: first frequency vs the chain's eigenvalue",
    "cantilever-EB": "Cantilever, 6 bonds: first frequency vs Euler-Bernoulli",
    "energy": "Free undamped cluster (7 spheres): max |E - E0| / E0",
}


def accuracy(csv_dir, fig_dir, n):
    rows = read(os.path.join(csv_dir, "accuracy.csv"))
    written = []
    for sid, scene in enumerate(n["scenes"]):
        mine = [r for r in rows if int(r["scene"]) == sid]
        if not mine:
            continue
        variants = sorted({int(r["variant"]) for r in mine})
        fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.6))
        for v in variants:
            pts = sorted((r["dt_fraction"], r["error"], r["wall_per_sim_second"]) for r in mine if int(r["variant"]) == v)
            label = n["variants"][v]
            line = a.loglog([p[0] for p in pts], [max(p[1], 1e-16) for p in pts], "o-", label=label)[0]
            ok = [p for p in pts if finite(p[2]) and p[1] < 1.0]
            b.loglog([p[2] for p in ok], [max(p[1], 1e-16) for p in ok], "o-", color=line.get_color(), label=label)
            for p in ok:
                b.annotate(f"{p[0]:g}", (p[2], max(p[1], 1e-16)), fontsize=6, alpha=0.7)
        a.axvline(0.2, color="k", ls=":", lw=1)
        a.text(0.2, a.get_ylim()[1], " recommended 0.2", va="top", fontsize=8)
        a.set_xlabel("dt / critical-step estimate")
        a.set_ylabel("relative error (1 = failed / blew up)")
        a.set_title("error vs time step", fontsize=10)
        b.set_xlabel("wall seconds per simulated second (scene runner, min of repeats)")
        b.set_ylabel("relative error")
        b.set_title("Pareto: error vs cost (labels: dt / dt_c)", fontsize=10)
        a.legend(fontsize=7)
        a.grid(True, which="both", alpha=0.3)
        b.grid(True, which="both", alpha=0.3)
        fig.suptitle(TITLES.get(scene, scene))
        fig.tight_layout()
        path = os.path.join(fig_dir, f"pareto_{scene}.png")
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written


def kernel_cost(csv_dir, fig_dir):
    rows = read(os.path.join(csv_dir, "kernel_cost.csv"))
    with open(os.path.join(csv_dir, "kernel_cost_names.txt")) as f:
        labels = [l.strip() for l in f if l.strip()]
    fig, ax = plt.subplots(figsize=(8, 3.8))
    ys = list(range(len(rows)))
    ax.barh(ys, [r["ns_per_bond_step"] for r in rows], color="tab:blue")
    for y, r in zip(ys, rows):
        ax.text(r["ns_per_bond_step"], y, f" {r['ns_per_bond_step']:.0f}", va="center", fontsize=8)
    ax.set_yticks(ys)
    ax.set_yticklabels([labels[int(r["variant"])] for r in rows], fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("ns per bond-step (batch of 1024, release, min of repeats)")
    ax.set_title("Cost of each degree of freedom and option")
    fig.tight_layout()
    path = os.path.join(fig_dir, "kernel_cost.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def stability_map(csv_dir, fig_dir, n):
    rows = read(os.path.join(csv_dir, "sweep.csv"))
    colours = {0: "tab:green", 1: "tab:orange", 2: "tab:red"}
    fig, ax = plt.subplots(figsize=(10, 5.5))
    params = n["parameters"]
    for r in rows:
        y = int(r["parameter"])
        x = r["log10_factor"]
        if params[y] == "overlap / R":
            x = -3.0 + 6.0 * (x + 15.0) / 14.0  # overlaps 1e-15..1e-1 on the same axis
        ax.scatter(x, y, s=120, marker="s", color=colours[int(r["verdict"])],
                   edgecolors="k" if r["flagged"] else "none", linewidths=1.2)
    ax.set_yticks(range(len(params)))
    labels = [p if p != "overlap / R" else "overlap / R (1e-15..1e-1)" for p in params]
    ax.set_yticklabels(labels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("log10(factor on the default)   [dt held at 0.2 x estimate of the defaults]")
    for v, name in [(0, "stable"), (1, "unstable/invalid but detected and reported"), (2, "silently wrong")]:
        ax.scatter([], [], marker="s", color=colours[v], label=name)
    ax.scatter([], [], marker="s", color="w", edgecolors="k", label="dt > recommended step (warned)")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2)
    ax.set_title("Stability map: one parameter at a time over six decades")
    fig.tight_layout()
    path = os.path.join(fig_dir, "stability_map.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


ASSEMBLIES = ["at rest, plain square root", "free fall, plain square root",
              "at rest, delta_eps = 1e-3 rb", "free fall, delta_eps = 1e-3 rb"]


def assemblies(csv_dir, fig_dir):
    rows = read(os.path.join(csv_dir, "assemblies.csv"))
    colours = {0: "tab:green", 1: "tab:orange", 2: "tab:red"}
    fig, ax = plt.subplots(figsize=(10, 3.4))
    for r in rows:
        ax.scatter(r["dt_fraction"], int(r["assembly"]), s=120, marker="s", color=colours[int(r["verdict"])],
                   edgecolors="k" if r["flagged"] else "none", linewidths=1.2)
    ax.set_yticks(range(len(ASSEMBLIES)))
    ax.set_yticklabels(ASSEMBLIES, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("dt / critical-step estimate (one bond, two spheres)")
    for v, name in [(0, "no bond broken"), (1, "bonds broken, warned at the run's start"),
                    (2, "bonds broken without a warning (silently wrong)")]:
        ax.scatter([], [], marker="s", color=colours[v], label=name)
    ax.scatter([], [], marker="s", color="w", edgecolors="k", label="dt > recommended step (warned)")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.25), ncol=2)
    ax.set_title("Bonded blocks (stress breakage) at rest and in free fall: nothing loads the bonds", fontsize=10)
    fig.tight_layout()
    path = os.path.join(fig_dir, "assemblies_map.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def coordination(csv_dir, fig_dir):
    rows = read(os.path.join(csv_dir, "coordination.csv"))
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for bond, label in [(0, "hysteretic, damped 0.1"), (1, "elastic, delta_eps = 1e-3 rb")]:
        pts = sorted((r["dt_fraction"], r["energy_gain"]) for r in rows if int(r["bond"]) == bond)
        ax.semilogy([p[0] for p in pts], [min(p[1], 1e6) for p in pts], "o-", label=label)
    ax.axhline(10, color="r", ls="--", lw=1)
    ax.text(0.2, 12, "blow-up threshold (energy x10)", fontsize=8, color="r")
    ax.axvline(0.2, color="k", ls=":", lw=1)
    ax.set_xlabel("dt / critical-step estimate (one bond, two spheres)")
    ax.set_ylabel("max energy / initial energy")
    ax.set_title("A sphere with six bonds: where the step really fails", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(fig_dir, "coordination_limit.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def rattle(csv_dir, fig_dir):
    rows = read(os.path.join(csv_dir, "rattle.csv"))
    fig, ax = plt.subplots(figsize=(6.5, 4))
    f = [r["dt_fraction"] for r in rows]
    ax.loglog(f, [r["peak"] for r in rows], "o-", label="plain square root: rattle amplitude")
    ax.loglog(f, [r["floor"] for r in rows], "k--", label="compression_noise_floor(dt)")
    ax.loglog(f, [max(r["peak_eps"], 1e-19) for r in rows], "s-", label="delta_eps = 1e-3 rb: stays at rest")
    ax.set_xlabel("dt / critical-step estimate")
    ax.set_ylabel("peak |compression| (m), start 1e-18 m at rest")
    ax.set_title("Unbounded square-root stiffness at zero compression", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(fig_dir, "sqrt_rattle.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    csv_dir, fig_dir = sys.argv[1], sys.argv[2]
    os.makedirs(fig_dir, exist_ok=True)
    n = names(csv_dir)
    written = accuracy(csv_dir, fig_dir, n)
    written += kernel_cost(csv_dir, fig_dir)
    written += stability_map(csv_dir, fig_dir, n)
    written += assemblies(csv_dir, fig_dir)
    written += coordination(csv_dir, fig_dir)
    written += rattle(csv_dir, fig_dir)
    for p in written:
        print("wrote", p)


if __name__ == "__main__":
    main()
