"""Watching bonds in both engines: counts, per-bond output, break log, VTK.

usage: check_watch.py --mode MODE --kind lammps|liggghts --engine EXE
                      [--mpiexec MPIEXEC] --workdir DIR

  counts   a chain of 8 spheres whose neighbours bond at step 1 and are then
           driven apart, bond k along x (tension) for odd k and along y
           (shear) for even k, each faster than the one before, so the bonds
           break one after the other in both modes. At every output step
           (thermo interval) the global counts (LAMMPS `compute pair
           granbond`, LIGGGHTS `compute bond/counter`) equal a recount of the
           per-bond dump (LAMMPS `compute granbond/local`, LIGGGHTS `compute
           pair/gran/local/bond`), no bond is in it twice, and (LAMMPS) the
           per-atom counts of `compute granbond/atom` add up to twice the
           intact bonds and equal each atom's rows. The break log has one line
           per broken bond, its modes add up to the counts (by mode, in
           LAMMPS), each line's stress reaches its limit, and a logged bond
           leaves the dump at its step. The first bond (pure tension) is
           hand-checked at every output against the closed forms of the
           virgin tension line: r0, stretch, normal force k_fn2 A |delta|,
           sigma = k_fn2 |delta|, its limit and ratio, delta_min. Runs on 1
           rank and, with --mpiexec, on 2 (the chain crosses the rank
           boundary): counts and break log equal those of 1 rank.
  vtk      tools/bonds_to_vtk.py on the dump and break log of `counts`
           (1 rank): every file parses with a strict reader and holds one
           line per dumped bond, its ends at the dumped centres and every
           field equal to the dump's; the .pvd lists every step.
"""

import argparse
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "support"))
sys.path.insert(0, os.path.join(ROOT, "tools"))

from deck_runner import Failure, main  # noqa: E402
import bonds_to_vtk  # noqa: E402

NSPHERES = 8
DIAMETER = 2e-3
DT = 1e-6
V0 = 0.1                 # relative speed of bond 1 (m/s); bond k: k V0
NRUN = 700
EVERY = 20
LAMBDA = 0.5
K_FN2 = 1e9              # tension stiffness per unit area (Pa/m)
SIGMA_MAX = 5e4
TAU_MAX = 1e4
AREA = math.pi * (LAMBDA * DIAMETER / 2) ** 2
FIELDS = ("status r0 r stretch normal_force shear_force force_x force_y force_z torque_i torque_j "
          "sigma sigma_max sigma_ratio tau tau_max tau_ratio delta_max delta_min twist_max twist_min "
          "bend_leading bend_opposite").split()
KEYWORDS = "id pos " + " ".join(FIELDS)
COLUMNS = ["id_i", "id_j", "x_i", "y_i", "z_i", "x_j", "y_j", "z_j"] + FIELDS

LAMMPS_BOND = ("lambda 0.5 k_fn1 1e9 ku_fn1 2e9 kc_fn1 5e8 k_fn2 1e9 ku_fn2 2e9 kc_fn2 5e8 "
               "k_ft 4e8 k_tn 4e8 ku_tn 4e8 kc_tn 4e8 k_tt 4e8 ku_tt 4e8 kc_tt 4e8 "
               "eta_fn 0 eta_ft 0 eta_tn 0 eta_tt 0 create_distance 2.05e-3 create_step 1")


def velocities():
    """Sphere k's velocity: bond k (spheres k, k+1) opens at k V0, along x
    for odd k, along y for even k."""
    v = [[0.0, 0.0, 0.0]]
    for k in range(1, NSPHERES):
        axis = 0 if k % 2 else 1
        nxt = list(v[-1])
        nxt[axis] += k * V0
        v.append(nxt)
    return v


def common_lines():
    lines = []
    for k in range(1, NSPHERES + 1):
        lines.append(f"create_atoms 1 single {(k - 1) * DIAMETER} 0.0 0.0 units box")
    lines.append(f"set atom * diameter {DIAMETER} density 2500")
    for k, (vx, vy, vz) in enumerate(velocities(), start=1):
        lines += [f"group g{k} id {k}", f"fix mv{k} g{k} move linear {vx} {vy} {vz}"]
    lines.append(f"timestep {DT}")
    return lines


def dump_lines(compute_style, lammps):
    cols = " ".join(f"c_bl[{c}]" for c in range(1, len(COLUMNS) + 1))
    # every digit: the checks compare with closed forms to 1e-12
    digits = "format float %.17g" if lammps else 'format "' + " ".join(["%.17g"] * len(COLUMNS)) + '"'
    return [f"compute bl all {compute_style} {KEYWORDS}",
            f"dump bonds all local {EVERY} bonds.dump {cols}", f"dump_modify bonds {digits}",
            "fix brk all bond/breaklog breaks.txt every 50"]


def lammps_deck():
    head = ["atom_style sphere", "atom_modify map array", "boundary f f f", "newton off",
            "comm_modify vel yes", "units si",
            "region box block -0.005 0.023 -0.006 0.006 -0.006 0.006 units box",
            "processors * 1 1", "create_box 1 box", "neighbor 0.0002 bin", "neigh_modify delay 0",
            "pair_style granbond",
            f"pair_coeff * * voigt 1e4 0 0 0 0.5 bond/nonlinear {LAMMPS_BOND} break stress {SIGMA_MAX} {TAU_MAX}"]
    counts = " ".join(f"${{c{k}}}" for k in range(1, 9))
    out = ["compute pg all pair granbond", "compute nb all granbond/atom",
           f"dump atoms all custom {EVERY} atoms.dump id c_nb", "variable step equal step"]
    out += [f"variable c{k} equal c_pg[{k}]" for k in range(1, 9)]
    out += [f'fix counts all print {EVERY} "${{step}} {counts}" file counts.txt screen no',
            "thermo_style custom step atoms c_pg[3] c_pg[2]", f"thermo {EVERY}", f"run {NRUN}"]
    return head + common_lines() + dump_lines("granbond/local", True) + out


def liggghts_deck(decks):
    head = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
            "communicate single vel yes", "units si",
            "region box block -0.005 0.023 -0.006 0.006 -0.006 0.006 units box",
            "processors * 1 1", "create_box 1 box", "neighbor 0.0002 bin", "neigh_modify delay 0",
            f"variable sigma index {SIGMA_MAX}", f"variable tau index {TAU_MAX}",
            f"include {decks}/bond_properties.in",
            "pair_style gran model hertz tangential history cohesion bond/nonlinear stressBreak on",
            "pair_coeff * *"]
    out = ["compute bc all bond/counter cumulative yes", "variable step equal step"]
    out += [f"variable c{k} equal c_bc[{k}]" for k in range(1, 4)]
    out += [f'fix counts all print {EVERY} "${{step}} ${{c1}} ${{c2}} ${{c3}}" file counts.txt screen no',
            "thermo_style custom step atoms c_bc[3] c_bc[2]", f"thermo {EVERY}", f"run {NRUN}"]
    return head + common_lines() + dump_lines("pair/gran/local/bond", False) + out


def mpi_prefix(mpiexec, n):
    if n == 1:
        return []
    prefix = [mpiexec, "-np", str(n)]
    if os.geteuid() == 0:
        prefix += ["--allow-run-as-root"]
    return prefix + ["--oversubscribe"]


def run(a, ranks, workdir):
    os.makedirs(workdir, exist_ok=True)
    lines = lammps_deck() if a.kind == "lammps" else liggghts_deck(os.path.join(ROOT, "tests", "adapters", "decks"))
    deck = os.path.join(workdir, "watch.in")
    with open(deck, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    cmd = mpi_prefix(a.mpiexec, ranks) + [a.engine, "-in", deck, "-log", "log.txt"]
    p = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300,
                       check=False)
    text = p.stdout.decode("utf-8", "replace")
    if p.returncode != 0:
        raise Failure(f"{' '.join(cmd)} exited with {p.returncode}:\n{text[-3000:]}")
    return workdir


def read_counts(path):
    counts = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                v = [float(x) for x in line.split()]
                counts[int(v[0])] = [int(round(x)) for x in v[1:]]
    return counts


def read_atoms(path):
    """{step: {id: count}} of a dump custom with columns id c_nb."""
    out, lines, k = {}, open(path, encoding="utf-8").read().splitlines(), 0
    while k < len(lines):
        step = int(lines[k + 1])
        n = int(lines[k + 3])
        rows = [lines[k + 9 + r].split() for r in range(n)]
        out[step] = {int(r[0]): int(float(r[1])) for r in rows}
        k += 9 + n
    return out


def check_counts(a, counts, dump, atoms, log):
    lammps = a.kind == "lammps"
    final = counts[max(counts)]
    created, broken, intact = final[0], final[1], final[2]
    if created != NSPHERES - 1:
        raise Failure(f"{created} bonds created, expected {NSPHERES - 1}: the deck does not bond the chain")
    if broken < 3 or intact == created:
        raise Failure(f"only {broken} bonds broke: the deck does not test breakage")
    partial = [s for s, c in counts.items() if 0 < c[1] < c[0]]
    if not partial:
        raise Failure("no output step with some bonds broken and some intact")
    for step, c in sorted(counts.items()):
        rows = dump.get(step)
        if rows is None:
            raise Failure(f"step {step}: counts printed but no per-bond dump")
        pairs = [(min(r["id_i"], r["id_j"]), max(r["id_i"], r["id_j"])) for r in rows]
        if len(set(pairs)) != len(pairs):
            raise Failure(f"step {step}: a bond is in the per-bond output twice: {sorted(pairs)}")
        recount = sum(1 for r in rows if r["status"] == 1)
        if recount != c[2] or len(rows) != c[2]:
            raise Failure(f"step {step}: {c[2]} intact bonds counted, the per-bond output has {recount} "
                          f"intact of {len(rows)} rows")
        if c[0] != c[1] + c[2]:
            raise Failure(f"step {step}: created {c[0]} != broken {c[1]} + intact {c[2]}")
        logged = [e for e in log if e["step"] <= step]
        if len(logged) != c[1]:
            raise Failure(f"step {step}: {c[1]} bonds broken, {len(logged)} lines in the break log")
        if lammps:
            by_mode = [sum(1 for e in logged if e["mode"] == m) for m in ("distance", "tension", "compression",
                                                                             "shear")]
            if by_mode != c[3:7]:
                raise Failure(f"step {step}: broken by mode {c[3:7]} (distance, tension, compression, shear), "
                              f"the break log has {by_mode}")
            per_atom = atoms[step]
            if sum(per_atom.values()) != 2 * c[2]:
                raise Failure(f"step {step}: per-atom counts add up to {sum(per_atom.values())}, "
                              f"twice the intact bonds is {2 * c[2]}")
            for atom, n in per_atom.items():
                mine = sum(1 for p in pairs if atom in p)
                if mine != n:
                    raise Failure(f"step {step}: atom {atom} has {n} bonds by compute granbond/atom, "
                                  f"{mine} in the per-bond output")
    print(f"ok: {len(counts)} output steps: counts = recount; final created {created}, broken {broken}")


def check_log(log, dump):
    modes = {e["mode"] for e in log}
    if not {"tension", "shear"} <= modes:
        raise Failure(f"break modes {sorted(modes)}: the deck should break bonds in tension and in shear")
    pairs = [(e["i"], e["j"]) for e in log]
    if len(set(pairs)) != len(pairs):
        raise Failure(f"a bond is logged twice: {pairs}")
    steps = sorted(dump)
    for e in log:
        stress, limit = (e["sigma"], e["sigma_max"]) if e["mode"] == "tension" else (e["tau"], e["tau_max"])
        if not stress >= limit > 0:
            raise Failure(f"{e}: its stress does not reach its limit")
        before = [s for s in steps if s < e["step"]]
        after = [s for s in steps if s >= e["step"]]
        has = lambda s: any({r["id_i"], r["id_j"]} == {e["i"], e["j"]} for r in dump[s])  # noqa: E731
        if before and not has(before[-1]):
            raise Failure(f"{e}: not in the per-bond output at step {before[-1]}, before its break")
        if after and has(after[0]):
            raise Failure(f"{e}: still in the per-bond output at step {after[0]}, after its break")
    print(f"ok: break log: {len(log)} lines, modes {sorted(modes)}")


def check_hand(dump):
    """Bond 1-2, pulled along x at V0 from step 0, bonded at step 1."""
    r0 = DIAMETER + V0 * DT
    checked = 0
    for step in sorted(dump):
        for row in dump[step]:
            if {row["id_i"], row["id_j"]} != {1, 2}:
                continue
            stretch = V0 * DT * step - V0 * DT
            want = {
                "status": 1.0, "r0": r0, "r": r0 + stretch, "stretch": stretch,
                "normal_force": -K_FN2 * AREA * stretch, "sigma": K_FN2 * stretch,
                "sigma_max": SIGMA_MAX, "sigma_ratio": K_FN2 * stretch / SIGMA_MAX,
                "tau_max": TAU_MAX, "delta_min": -stretch, "delta_max": 0.0,
            }
            # a length carries ~1e-14 m of rounding (positions near 1e-2 m
            # moved step by step); a force or stress carries that times its
            # stiffness, plus 1e-12 of itself
            length = 1e-14
            tol = {"status": 0.0, "sigma_max": 0.0, "tau_max": 0.0, "normal_force": K_FN2 * AREA * length,
                   "sigma": K_FN2 * length, "sigma_ratio": K_FN2 * length / SIGMA_MAX}
            for name, value in want.items():
                if abs(row[name] - value) > tol.get(name, length) + 1e-12 * abs(value):
                    raise Failure(f"step {step}: bond 1-2 {name} = {row[name]!r}, closed form {value!r}")
            zero = {"shear_force": K_FN2 * AREA * length, "torque_i": K_FN2 * AREA * length * DIAMETER,
                    "torque_j": K_FN2 * AREA * length * DIAMETER, "tau": K_FN2 * length,
                    "tau_ratio": K_FN2 * length / TAU_MAX}
            for name, bound in zero.items():
                if abs(row[name]) > bound:
                    raise Failure(f"step {step}: bond 1-2 (pure tension) has {name} = {row[name]!r}")
            checked += 1
    if checked < 10:
        raise Failure(f"bond 1-2 checked at only {checked} outputs")
    print(f"ok: bond 1-2 equals the closed forms at {checked} outputs")


def counts_mode(a):
    results = {}
    for ranks in ([1, 2] if a.mpiexec else [1]):
        wd = run(a, ranks, os.path.join(a.workdir, f"np{ranks}"))
        counts = read_counts(os.path.join(wd, "counts.txt"))
        dump = bonds_to_vtk.read_dump_local(os.path.join(wd, "bonds.dump"), COLUMNS)
        log = bonds_to_vtk.read_break_log(os.path.join(wd, "breaks.txt"))
        atoms = read_atoms(os.path.join(wd, "atoms.dump")) if a.kind == "lammps" else {}
        print(f"== {a.kind}, {ranks} rank(s)")
        check_counts(a, counts, dump, atoms, log)
        check_log(log, dump)
        check_hand(dump)
        results[ranks] = (counts, open(os.path.join(wd, "breaks.txt"), encoding="utf-8").read())
    if 2 in results:
        if results[2][0] != results[1][0]:
            raise Failure("the counts on 2 ranks differ from those on 1")
        if results[2][1] != results[1][1]:
            raise Failure("the break log on 2 ranks differs from that on 1")
        print("ok: 2 ranks: counts and break log equal those of 1 rank")


def vtk_mode(a):
    wd = run(a, 1, os.path.join(a.workdir, "np1"))
    out = os.path.join(wd, "vtk")
    cmd = [sys.executable, os.path.join(ROOT, "tools", "bonds_to_vtk.py"), os.path.join(wd, "bonds.dump"),
           "--columns", KEYWORDS, "--breaklog", os.path.join(wd, "breaks.txt"), "--out", out]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=False)
    if p.returncode != 0:
        raise Failure(f"{' '.join(cmd)} exited with {p.returncode}:\n{p.stdout.decode()}")
    dump = bonds_to_vtk.read_dump_local(os.path.join(wd, "bonds.dump"), COLUMNS)
    log = bonds_to_vtk.read_break_log(os.path.join(wd, "breaks.txt"))
    series = bonds_to_vtk.read_pvd(os.path.join(out, "bonds.pvd"))
    if [s for s, _ in series] != sorted(dump):
        raise Failure(f"bonds.pvd lists steps {[s for s, _ in series]}, the dump has {sorted(dump)}")
    lines_seen = 0
    for step, name in series:
        poly = bonds_to_vtk.read_vtp(os.path.join(out, name))
        rows = dump[step]
        if poly["lines"] != [(2 * k, 2 * k + 1) for k in range(len(rows))]:
            raise Failure(f"step {step}: lines {poly['lines'][:3]}...: expected (2k, 2k + 1), one per each of "
                          f"{len(rows)} bonds")
        for k, row in enumerate(rows):
            ends = (poly["points"][2 * k], poly["points"][2 * k + 1])
            want = ((row["x_i"], row["y_i"], row["z_i"]), (row["x_j"], row["y_j"], row["z_j"]))
            if ends != want:
                raise Failure(f"step {step}, bond {k}: ends {ends}, dumped centres {want}")
            for field in FIELDS + ["id_i", "id_j"]:
                if poly["cells"][field][k] != row[field]:
                    raise Failure(f"step {step}, bond {k}: {field} {poly['cells'][field][k]!r} in the VTK file, "
                                  f"{row[field]!r} in the dump")
        breaks = bonds_to_vtk.read_vtp(os.path.join(out, name.replace("bonds_", "breaks_")))
        gone = [e for e in log if e["step"] <= step]
        if len(breaks["points"]) != len(gone) or breaks["verts"] != list(range(len(gone))):
            raise Failure(f"step {step}: {len(breaks['points'])} broken bonds in the VTK file, {len(gone)} logged")
        for k, e in enumerate(gone):
            if breaks["points"][k] != tuple(e["x"]) or breaks["points_data"]["sigma"][k] != e["sigma"]:
                raise Failure(f"step {step}: broken bond {k} differs from the break log line {e}")
        lines_seen += len(rows)
    if lines_seen == 0:
        raise Failure("no bond in any VTK file")
    print(f"ok: {len(series)} VTK files, {lines_seen} bond lines, fields equal to the dump")


def run_mode(a):
    if a.mode == "counts":
        counts_mode(a)
    elif a.mode == "vtk":
        vtk_mode(a)
    else:
        raise Failure(f"unknown mode {a.mode}")


if __name__ == "__main__":
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True)
    p.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    p.add_argument("--engine", required=True)
    p.add_argument("--mpiexec")
    p.add_argument("--workdir", required=True)
    args = p.parse_args()
    main(lambda: run_mode(args))
