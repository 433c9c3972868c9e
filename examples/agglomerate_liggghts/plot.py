"""Plots of the LIGGGHTS agglomerate impact (in.agglomerate).

Usage: plot.py OUT_DIR   (the run's working directory: post/, log.liggghts)

Reads the `dump local` frames post/bonds_<step>.txt (atom ids and the bond
state slot `status`: 1 = intact) and the atom dumps post/atoms_<step>.txt.
Reads post/breaks.txt (fix bond/breaklog) for the break modes.
Writes into OUT_DIR:
  broken_bonds.png    bonds broken over time, by mode (and the kinetic energy)
  fragment_sizes.png  fragment size distribution at the end (fragments =
                      connected components of the spheres over intact bonds)
  fragments.png       the final state seen from the side, coloured by fragment
  fragments.vtk       the final state with fragment id and size per sphere
                      (ParaView: Glyph, scale by radius, colour by fragment_size)
  fragments.csv       one row per fragment: size
  post/vtk/           the bond network (bonds.pvd, breaks.pvd) of post/network.dump
  network.png         that network at three steps, seen from the side
  budget.png          kinetic energy and the bonds' energy budget
                      (post/energy.txt) stacked over time
Analysis only (counting and graph components): no physics here.
"""

import glob
import os
import re
import subprocess
import sys
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

DT = 1.0e-6  # the deck's time step (s)


def frames(pattern):
    """{step: path} of the dump files matching post/<pattern>_<step>.txt."""
    out = {}
    for path in glob.glob(pattern):
        m = re.search(r"_(\d+)\.txt$", path)
        if m:
            out[int(m.group(1))] = path
    return dict(sorted(out.items()))


def read_dump(path):
    """Body rows of a LAMMPS dump (local or custom) as a float array."""
    with open(path) as f:
        lines = f.readlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES") or line.startswith("ITEM: ATOMS"))
    rows = [line.split() for line in lines[start + 1:] if line.strip()]
    header = lines[start].split()[2:]
    return header, np.array(rows, dtype=float).reshape(len(rows), len(header))


def intact_bonds(path):
    """Set of (id_low, id_high) pairs whose bond is intact. A pair that
    straddles two MPI ranks can be reported by both: the set dedupes it."""
    _, rows = read_dump(path)
    bonds = set()
    for i, j, status in rows:
        if int(round(status)) == 1:
            a, b = int(i), int(j)
            bonds.add((min(a, b), max(a, b)))
    return bonds


def components(ids, bonds):
    """Fragment label per atom id: union-find over the intact bonds."""
    parent = {i: i for i in ids}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in bonds:
        if a in parent and b in parent:
            ra, rb = find(a), find(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    return {i: find(i) for i in ids}


def thermo(log):
    """(step, ke) columns of the thermo output in the log, if present."""
    steps, ke = [], []
    if not os.path.exists(log):
        return steps, ke
    cols = None
    with open(log) as f:
        for line in f:
            words = line.split()
            if words[:2] == ["Step", "Time"]:
                cols = words
                continue
            if cols and len(words) == len(cols):
                try:
                    vals = [float(w) for w in words]
                except ValueError:
                    cols = None
                    continue
                steps.append(vals[0])
                key = "c_ke" if "c_ke" in cols else "ke"
                ke.append(vals[cols.index(key)] if key in cols else float("nan"))
            elif cols and words[:1] == ["Loop"]:
                cols = None
    return steps, ke


def write_vtk(path, ids, xyz, radius, label, size):
    with open(path, "w") as f:
        n = len(ids)
        f.write("# vtk DataFile Version 3.0\ngranbond agglomerate fragments\nASCII\nDATASET POLYDATA\n")
        f.write(f"POINTS {n} double\n")
        for p in xyz:
            f.write(f"{p[0]:.9e} {p[1]:.9e} {p[2]:.9e}\n")
        f.write(f"VERTICES {n} {2 * n}\n")
        for k in range(n):
            f.write(f"1 {k}\n")
        f.write(f"POINT_DATA {n}\n")
        for name, values, fmt in (("id", ids, "d"), ("fragment", label, "d"), ("fragment_size", size, "d"),
                                  ("radius", radius, ".6e")):
            f.write(f"SCALARS {name} {'int' if fmt == 'd' else 'double'} 1\nLOOKUP_TABLE default\n")
            f.write("\n".join(format(int(v) if fmt == "d" else v, fmt) for v in values) + "\n")


def main(out):
    post = os.path.join(out, "post")
    bond_frames = frames(os.path.join(post, "bonds_*.txt"))
    atom_frames = frames(os.path.join(post, "atoms_*.txt"))
    if not bond_frames or not atom_frames:
        sys.exit(f"plot.py: no dumps under {post}")

    # broken bonds over time: bonds created at step 1 minus those intact
    counts = {step: len(intact_bonds(path)) for step, path in bond_frames.items()}
    created = max(counts.values())
    steps = [s for s in counts if s >= 1]
    t_ms = np.array(steps) * DT * 1e3
    broken = np.array([created - counts[s] for s in steps])

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    # by mode, from the break log (fix bond/breaklog: step id_i id_j x y z mode sigma tau)
    modes = {}
    log_path = os.path.join(post, "breaks.txt")
    if os.path.exists(log_path):
        with open(log_path) as f:
            for line in f:
                words = line.split()
                if len(words) >= 7 and not line.startswith("#"):
                    modes.setdefault(words[6], []).append(int(words[0]))
    for k, (mode, events) in enumerate(sorted(modes.items())):
        events.sort()
        ax.step(np.array(events) * DT * 1e3, np.arange(1, len(events) + 1), where="post",
                color=f"C{k + 4}", label=f"{mode} (break log)")
    ax.plot(t_ms, broken, "o-", ms=3, color="C3", label="all (dump local: intact bonds)")
    ax.set_xlabel("time (ms)")
    ax.set_ylabel(f"bonds broken (of {created} created)")
    ax.set_title("LIGGGHTS agglomerate impact: broken bonds")
    th_steps, ke = thermo(os.path.join(out, "log.liggghts"))
    if th_steps:
        ax2 = ax.twinx()
        ax2.plot(np.array(th_steps) * DT * 1e3, np.array(ke) * 1e3, "--", color="C0", label="kinetic energy")
        ax2.set_ylabel("kinetic energy (mJ)", color="C0")
        lines = ax.get_lines() + ax2.get_lines()
        ax.legend(lines, [l.get_label() for l in lines], loc="center left", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "broken_bonds.png"), dpi=120)
    plt.close(fig)

    # fragments at the end
    last = max(atom_frames)
    header, atoms = read_dump(atom_frames[last])
    col = {name: k for k, name in enumerate(header)}
    ids = atoms[:, col["id"]].astype(int)
    final_bonds = intact_bonds(bond_frames[max(bond_frames)])
    label_of = components(ids, final_bonds)
    sizes_by_label = Counter(label_of.values())
    sizes = sorted(sizes_by_label.values(), reverse=True)
    with open(os.path.join(out, "fragments.csv"), "w") as f:
        f.write("size\n" + "".join(f"{s}\n" for s in sizes))

    hist = Counter(sizes)
    xs = sorted(hist)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(xs, [hist[x] for x in xs], "o")
    ax.set_xlabel("fragment size (spheres)")
    ax.set_ylabel("number of fragments")
    ax.set_title(f"Fragments at t = {last * DT * 1e3:g} ms: {len(sizes)} "
                 f"(largest {sizes[0]} of {len(ids)} spheres)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fragment_sizes.png"), dpi=120)
    plt.close(fig)

    xyz = atoms[:, [col["x"], col["y"], col["z"]]]
    labels = np.array([label_of[i] for i in ids])
    size = np.array([sizes_by_label[l] for l in labels])
    rank = {l: k for k, (l, _) in enumerate(sizes_by_label.most_common())}
    colour = np.array([rank[l] for l in labels])
    fig, ax = plt.subplots(figsize=(7, 4.2))
    big = size > 1
    ax.scatter(xyz[~big, 0] * 1e3, xyz[~big, 2] * 1e3, s=2, c="0.6", label="single spheres")
    ax.scatter(xyz[big, 0] * 1e3, xyz[big, 2] * 1e3, s=4, c=colour[big] % 20, cmap="tab20")
    ax.axhline(0.0, color="k", lw=1)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title("Final state (side view), coloured by fragment")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fragments.png"), dpi=120)
    plt.close(fig)

    write_vtk(os.path.join(out, "fragments.vtk"), ids, xyz, atoms[:, col["radius"]], labels, size)
    print(f"agglomerate: {len(ids)} spheres, {created} bonds created, {created - counts[max(counts)]} broken, "
          f"{len(sizes)} fragments (largest {sizes[0]})")
    for name in ("broken_bonds.png", "fragment_sizes.png", "fragments.png", "fragments.vtk"):
        print(f"wrote {os.path.join(out, name)}")
    network(out)
    budget(out)


def budget(out):
    """The bonds' energy budget of post/energy.txt stacked over time with
    the kinetic energy (budget.png, the LAMMPS example's plot_budget.py)."""
    source = os.path.join(out, "post", "energy.txt")
    if not os.path.exists(source):
        return
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lammps_agglomerate", "plot_budget.py")
    subprocess.run([sys.executable, script, source, os.path.join(out, "budget.png"),
                    "LIGGGHTS cohesion bond/nonlinear: the bonds' energy budget, ball into a wall at 3 m/s"],
                   check=True)


def network(out):
    """The bond network of post/network.dump and post/breaks.txt as VTK
    lines (post/vtk, tools/bonds_to_vtk.py), drawn at three steps
    (network.png, tools/plot_bond_network.py)."""
    post = os.path.join(out, "post")
    dump = os.path.join(post, "network.dump")
    if not os.path.exists(dump):
        return
    tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
    cols = "id pos status stretch normal_force shear_force sigma_ratio tau_ratio"
    vtk = os.path.join(post, "vtk")
    subprocess.run([sys.executable, os.path.join(tools, "bonds_to_vtk.py"), dump, "--columns", cols,
                    "--breaklog", os.path.join(post, "breaks.txt"), "--out", vtk], check=True)
    with open(dump, encoding="utf-8") as f:
        lines = f.read().splitlines()
    steps = [int(lines[k + 1]) for k, line in enumerate(lines) if line == "ITEM: TIMESTEP"]
    picks = [steps[1], steps[len(steps) // 2], steps[-1]] if len(steps) > 2 else steps
    subprocess.run([sys.executable, os.path.join(tools, "plot_bond_network.py"), vtk, "--steps",
                    *[str(s) for s in picks], "--field", "sigma_ratio", "--view", "xz", "--out",
                    os.path.join(out, "network.png"),
                    "--title", "cohesion bond/nonlinear: intact bonds coloured by sigma/sigma_max, broken by mode"],
                   check=True)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
