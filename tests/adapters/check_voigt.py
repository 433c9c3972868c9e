"""Engine-level checks of `model voigt`, `tangential voigt` and
`rolling_friction voigt` (Python 3 stdlib only).

    check_voigt.py --engine <liggghts launcher> --workdir <dir> --check <name> [--mpiexec MPIEXEC]

Each check is one claim; it prints PASS or FAIL: <why> and exits non-zero on
failure. Decks: decks/ here; runs go through tests/support/deck_runner.py.
"""

import argparse
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import deck_runner  # noqa: E402
from deck_runner import Failure, names_a_core_entry, read_table  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.join(HERE, "decks")
PLANE_STL = os.path.join(deck_runner.DECKS, "plane.stl")

R = 1.0e-3                                  # radius of sphere 1 (m)
MASS = 2500.0 * 4.0 / 3.0 * math.pi * R**3  # seed Table 1 sphere
HOOKE = "model hooke/stiffness tangential history"
HOOKE_SETTINGS = "absolute_damping on limitForce on"   # limitForce = voigt's noAttraction
COLUMNS = "step x1 y1 x2 y2 vx1 vy1 vx2 vy2 wz1 wz2 fx1 fy1 fx2 fy2 tz1 tz2".split()
NORMAL = ["x1", "x2", "vx1", "vx2", "fx1", "fx2"]          # along the line of centres (x)
TANGENTIAL = ["y1", "y2", "vy1", "vy2", "wz1", "wz2", "fy1", "fy2", "tz1", "tz2"]


def run(args, deck, variables, tag, command=None):
    """Runs decks/<deck> in the work directory; returns (exit code, output)."""
    return deck_runner.run_deck(command or [args.engine], os.path.join(DECKS, deck), args.workdir,
                                 variables, log=f"log.{tag}")


def pair_run(args, tag, **variables):
    variables.setdefault("nrun", 20000)
    variables["out"] = f"{tag}.txt"
    rc, text = run(args, "voigt_pair.in", variables, tag)
    if rc != 0:
        raise Failure(f"pair run {tag} exited with {rc}:\n{text[-2000:]}")
    rows = read_table(os.path.join(args.workdir, f"{tag}.txt"))
    return [dict(zip(COLUMNS, r)) for r in rows]


def max_relative_difference(a, b, column, upto=None):
    """max |a - b| over the run, relative to the largest |a| of the column."""
    n = min(len(a), len(b)) if upto is None else upto
    scale = max(abs(r[column]) for r in a[:n]) or 1.0
    return max(abs(x[column] - y[column]) for x, y in zip(a[:n], b[:n])) / scale


def overlap(row, d2=2.0e-3):
    return R + d2 / 2 - math.hypot(row["x2"] - row["x1"], row["y2"] - row["y1"])


def expect(condition, message):
    if not condition:
        raise Failure(message)


# --- claims ---------------------------------------------------------------

def head_on_equals_hooke_stiffness(args):
    """Head-on, Table 1: voigt and hooke/stiffness + history are the same
    law; only the order of floating-point operations may differ."""
    v = pair_run(args, "voigt_head_on")
    h = pair_run(args, "hooke_head_on", models=HOOKE, settings=HOOKE_SETTINGS)
    expect(any(r["fx1"] != 0.0 for r in v), "the spheres never touched")
    for c in COLUMNS[1:]:
        d = max_relative_difference(v, h, c)
        expect(d <= 1e-12, f"{c} differs by {d:.3e} (relative) from hooke/stiffness")


def first_sliding_step(rows, mu=0.5):
    for k, r in enumerate(rows):
        fn = abs(r["fx1"])   # the normal stays close to x in these collisions
        if fn > 0 and math.hypot(r["fy1"], 0.0) >= 0.999 * mu * fn:
            return k
    return len(rows)


def oblique_equals_hooke_stiffness_up_to_lever_arm(args):
    """Oblique, Table 1. Before sliding, the only difference is the lever arm:
    the spec (and voigt) uses R_i, LIGGGHTS's surface model R_i - delta/2, for
    the rotational slip velocity and for the torque. So (1) along the line of
    centres the runs agree to second order, (2) tangential quantities differ
    by at most about max(delta)/R, and (3) that difference shrinks in
    proportion to the overlap (a 10x slower impact gives a 10x smaller one).
    (During the last steps of contact, when |Ft| reaches mu |Fn|, LIGGGHTS also
    drops the tangential dashpot while voigt caps spring + dashpot, as the
    spec says; those steps are left out.)"""
    ratios = []
    for vn, gap in ((0.1, 1e-5), (0.01, 1e-6)):
        v = pair_run(args, f"voigt_oblique_{vn}", vn=vn, vt=0.2 * vn, gap=gap)
        h = pair_run(args, f"hooke_oblique_{vn}", vn=vn, vt=0.2 * vn, gap=gap, models=HOOKE,
                     settings=HOOKE_SETTINGS)
        stop = min(first_sliding_step(v), first_sliding_step(h))
        touching = [k for k in range(stop) if v[k]["fx1"] != 0.0]
        expect(len(touching) > 1000, f"vn {vn}: only {len(touching)} steps in contact before sliding")
        lever = max(overlap(r) for r in v[:stop]) / R
        for c in NORMAL:
            d = max_relative_difference(v, h, c, stop)
            expect(d <= 1e-2 * lever, f"vn {vn}: {c} differs by {d:.3e}, more than second order in delta/R = {lever:.3e}")
        worst = max(max_relative_difference(v, h, c, stop) for c in TANGENTIAL)
        expect(worst <= 1.5 * lever, f"vn {vn}: tangential difference {worst:.3e} exceeds 1.5 max(delta)/R = {1.5 * lever:.3e}")
        expect(worst > 0.0, f"vn {vn}: no difference at all: is the lever arm R - delta/2 now?")
        ratios.append(worst / lever)
    expect(0.7 <= ratios[1] / ratios[0] <= 1.3,
           f"tangential difference not proportional to the overlap: ratios {ratios}")


def voigt_normal_feeds_stock_tangential(args):
    """`model voigt tangential history` equals hooke/stiffness + history: the
    normal model hands Fn, kn, kt, gamman, gammat on through sidata."""
    kw = dict(vt=0.02, d2=0.0012)
    v = pair_run(args, "voigt_history", models="model voigt tangential history", **kw)
    h = pair_run(args, "hooke_history", models=HOOKE, settings=HOOKE_SETTINGS, **kw)
    for c in COLUMNS[1:]:
        d = max_relative_difference(v, h, c)
        expect(d <= 1e-12, f"{c} differs by {d:.3e} (relative)")


def whole_contact_equals_parts(args):
    """voigt x voigt x voigt advances the contact in one core call; the same
    physics through the separate parts (hooke/stiffness is voigt's normal law)
    gives the same run, rolling included (unequal spheres spin differently)."""
    kw = dict(vt=0.02, d2=0.0012)
    whole = pair_run(args, "whole", models="model voigt tangential voigt rolling_friction voigt", **kw)
    parts = pair_run(args, "parts", models="model hooke/stiffness tangential voigt rolling_friction voigt",
                     settings=HOOKE_SETTINGS, **kw)
    norolling = pair_run(args, "norolling", models="model voigt tangential voigt", **kw)
    for c in COLUMNS[1:]:
        d = max_relative_difference(whole, parts, c)
        expect(d <= 1e-12, f"{c} differs by {d:.3e} (relative)")
    d = max_relative_difference(whole, norolling, "wz2")
    expect(d > 1e-3, f"rolling resistance changed the spin of sphere 2 by only {d:.3e}")


def restitution_and_contact_time(args):
    """Head-on, no attraction off: e = exp(-pi z/sqrt(1-z^2)), z = gamma_n /
    (2 sqrt(k_n m_eff)); contact time pi / sqrt(k_n/m_eff - (gamma_n/2m_eff)^2)."""
    kn, gn, dt, vn = 1.0e4, 0.05, 1.0e-8, 0.1
    m_eff = MASS / 2
    zeta = gn / (2 * math.sqrt(kn * m_eff))
    e_exact = math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2))
    t_exact = math.pi / math.sqrt(kn / m_eff - (gn / (2 * m_eff)) ** 2)
    rows = pair_run(args, "restitution", gn=gn, settings="noAttraction off")
    touching = [r for r in rows if r["fx1"] != 0.0]
    expect(rows[-1]["fx1"] == 0.0, "still in contact at the end of the run")
    e = (rows[-1]["vx2"] - rows[-1]["vx1"]) / vn
    t = len(touching) * dt
    expect(abs(e - e_exact) <= 1e-3 * e_exact, f"e = {e:.6f}, closed form {e_exact:.6f}")
    expect(abs(t - t_exact) <= 2 * dt, f"contact time {t:.6e} s, closed form {t_exact:.6e} s")
    clamped = pair_run(args, "restitution_clamped", gn=gn)
    expect(all(r["fx1"] <= 0.0 for r in clamped), "noAttraction on (default): an attractive force")
    expect(any(r["fx1"] > 0.0 for r in rows), "noAttraction off: the dashpot never pulled")
    e_clamped = (clamped[-1]["vx2"] - clamped[-1]["vx1"]) / vn
    expect(e_clamped > e, f"clamping should raise e: {e_clamped:.6f} vs {e:.6f}")


BAD_VALUES = [  # deck variable, property named in the error
    ("kn", "kn"), ("gn", "gamman_abs"), ("kt", "kt"), ("gt", "gammat_abs"),
    ("mu", "coefficientFriction"), ("mur", "coefficientRollingFriction"),
    ("kr", "rollingStiffness"), ("gr", "rollingDamping"), ("er", "rollingViscousDamping"),
]


def bad_values_are_named(args):
    """A negative value of each property stops the run with an error naming it."""
    models = "model voigt tangential voigt rolling_friction voigt"
    for variable, name in BAD_VALUES:
        rc, text = run(args, "voigt_pair.in", {variable: -1, "nrun": 1, "models": models, "out": "bad.txt"},
                       f"bad_{variable}")
        errors = [l for l in text.splitlines() if "ERROR" in l]
        expect(rc != 0 and errors, f"{name} = -1 was accepted")
        expect(any(f"({name})" in l for l in errors), f"{name} = -1: error does not name it: {errors}")
        expect(any(f"({name})" in l and " voigt (" in l for l in errors),
               f"{name} = -1: error does not name the sub-model: {errors}")
        expect(not any(names_a_core_entry(l) for l in errors),
               f"{name} = -1: error names a C entry of the core: {errors}")


def wall_sliding_turns_to_rolling(args):
    """A sphere launched sliding on a plane wall (primitive and mesh) ends
    rolling at 5/7 of its speed; rolling resistance slows it further."""
    speeds = []
    for wall in (1, 0):
        for rolling in (False, True):
            models = "model voigt tangential voigt" + (" rolling_friction voigt" if rolling else "")
            rc, text = run(args, "voigt_wall.in", {"wall": wall, "models": models, "stl": PLANE_STL},
                           f"wall{wall}{rolling}")
            lines = [l for l in text.splitlines() if l.startswith("RESULT")]
            expect(rc == 0 and lines, f"wall {wall} rolling {rolling}: run failed:\n{text[-2000:]}")
            vx, wy = (float(x) for x in lines[-1].split()[1:3])
            speeds.append((wall, rolling, vx, wy))
    for wall, rolling, vx, wy in speeds:
        if not rolling:
            expect(abs(vx - 5 / 7 * 0.1) <= 1e-3 * 0.1, f"wall {wall}: vx {vx}, expected 5/7 v0")
            expect(abs(wy * R - vx) <= 1e-3 * vx, f"wall {wall}: not rolling: w R = {wy * R}, v = {vx}")
    free = {w: vx for w, r, vx, _ in speeds if not r}
    resisted = {w: vx for w, r, vx, _ in speeds if r}
    for w in free:
        expect(resisted[w] < free[w] - 1e-3, f"wall {w}: rolling resistance did not slow the sphere")
    expect(free[0] == free[1] and resisted[0] == resisted[1], f"mesh and primitive wall differ: {speeds}")


PACKING_COLUMNS = "id x y z vx vy vz fx fy fz tqx tqy tqz wx wy wz".split()
COMBINATIONS = {  # voigt with a stock or granbond model in another slot
    "no_history": ("model voigt tangential no_history", "none.in"),
    "epsd2": ("model voigt tangential voigt rolling_friction epsd2", "none.in"),
    "bond_nonlinear": ("model voigt tangential voigt cohesion bond/nonlinear rolling_friction voigt",
                       os.path.join(deck_runner.DECKS, "bond_properties.in")),
}


def packing(args, tag, models, extra="none.in", command=None, nrun=2000):
    """Runs the packing deck; returns its per-atom rows and the raw output."""
    out = f"{tag}.txt"
    variables = {"models": models, "extra": os.path.join(DECKS, extra), "nrun": nrun, "out": out,
                 "friction": 1 if extra == "none.in" else 0}
    rc, text = run(args, "voigt_packing.in", variables, tag, command)
    errors = [l for l in text.splitlines() if "ERROR" in l]
    expect(rc == 0 and not errors, f"{models}: exit {rc}, errors {errors}:\n{text[-2000:]}")
    path = os.path.join(args.workdir, out)
    with open(path, "rb") as f:
        raw = f.read()
    # two snapshots (start, end); an atom is known by its start position,
    # as ids are handed out rank by rank
    snapshots = [[line.split() for line in snap.split("ITEM:")[0].splitlines()[1:] if line.strip()]
                 for snap in raw.decode().split("ITEM: ATOMS")[1:]]
    expect(len(snapshots) == 2, f"{models}: {len(snapshots)} snapshots written, expected 2")
    start = {r[0]: tuple(r[1:4]) for r in snapshots[0]}
    rows = sorted((dict(zip(PACKING_COLUMNS, (float(v) for v in r)), start=start[r[0]]) for r in snapshots[1]),
                  key=lambda r: r["start"])
    expect(len(rows) == 180, f"{models}: {len(rows)} atoms written, expected 180")
    return rows, raw


def combination_runs(args):
    """Each listed combination with voigt runs the packing without an error,
    with finite positions, velocities, forces and torques at the end, and
    contacts still acting then (a sideways force and a torque on at least a
    tenth of the spheres)."""
    models, extra = COMBINATIONS[args.combination]
    rows, _ = packing(args, args.combination, models, extra)
    bad = [r["id"] for r in rows if not all(math.isfinite(r[c]) for c in PACKING_COLUMNS)]
    expect(not bad, f"{models}: non-finite values for atoms {bad[:10]}")
    acting = sum(1 for r in rows if abs(r["fx"]) + abs(r["fy"]) > 0.0 and abs(r["tqx"]) + abs(r["tqy"]) > 0.0)
    expect(acting >= len(rows) // 10, f"{models}: contacts act on only {acting} of {len(rows)} spheres")
    print(f"{models}: {len(rows)} spheres, all finite, contacts acting on {acting}")


def linear_bond_with_contact(args):
    """voigt with LIGGGHTS-INL's linear bond (cohesion bond): the bond of
    spheres 1 and 2 holds and acts (sphere 1, sent away at 0.05 m/s, is
    pulled back), sphere 3, too far to bond, bounces off sphere 2 by the
    Voigt contact, and the total momentum stays to round-off."""
    rc, text = run(args, "voigt_linear_bond.in", {"out": "linear_bond.txt"}, "linear_bond")
    errors = [l for l in text.splitlines() if "ERROR" in l]
    expect(rc == 0 and not errors, f"exit {rc}, errors {errors}:\n{text[-2000:]}")
    rows = read_table(os.path.join(args.workdir, "linear_bond.txt"))
    expect(len(rows) == 40, f"{len(rows)} rows written, expected 40")
    expect(all(r[1] == 1 for r in rows), f"bonds intact: {[r[1] for r in rows]}, expected 1 throughout")
    pulled = max(abs(r[5] + 0.05) for r in rows if r[0] <= 2300)
    expect(pulled > 0.01, f"sphere 1 kept {rows[0][5]} m/s: the bond does not act")
    expect(rows[-1][6] > 0.0, f"sphere 3 ends at vx {rows[-1][6]}: it did not bounce off sphere 2")
    mass3 = 2500 * 4 / 3 * math.pi * R**3
    drift = max(abs(r[k] - rows[0][k]) for r in rows for k in (2, 3, 4)) / (mass3 * 0.5)
    expect(drift <= 1e-12, f"the total momentum drifts by {drift:.3g} of sphere 3's")
    print(f"bond intact, sphere 1 pulled by {pulled:.3g} m/s, sphere 3 back at {rows[-1][6]:.3g} m/s, "
          f"momentum drift {drift:.3g} of sphere 3's")


# Relative to the largest value of the column. The engine's sum of the
# contact forces on a sphere runs in neighbour-list order, which depends on
# the decomposition, so 1 and 2 ranks differ by round-off that grows slowly
# in the collapsing block (measured after 2000 steps: 3e-11; stock
# hooke/stiffness + history + epsd2: 2e-11); a contact history lost or
# mis-signed at the rank boundary shows up at 1e-3 or more.
RANKS_TOLERANCE = 1e-8


def two_ranks_match_one(args):
    """voigt x voigt x voigt on the packing: 2 MPI ranks (their boundary cuts
    the block, so contacts and histories cross it) end in the same state as 1,
    up to round-off."""
    expect(args.mpiexec, "--mpiexec is required")
    models = "model voigt tangential voigt rolling_friction voigt"
    serial, _ = packing(args, "np1", models)
    prefix = [args.mpiexec, "-np", "2"]
    if os.geteuid() == 0:
        prefix += ["--allow-run-as-root"]
    prefix += ["--oversubscribe", args.engine]
    parallel, _ = packing(args, "np2", models, command=prefix)
    expect([r["start"] for r in serial] == [r["start"] for r in parallel], "the runs started from other positions")
    for c in PACKING_COLUMNS[1:]:
        scale = max(abs(r[c]) for r in serial) or 1.0
        d = max(abs(a[c] - b[c]) for a, b in zip(serial, parallel)) / scale
        expect(d <= RANKS_TOLERANCE, f"{c} differs by {d:.3e} (relative to its largest value)")
        print(f"{c}: 1 vs 2 ranks differ by {d:.1e}")


CHECKS = {f.__name__: f for f in (
    head_on_equals_hooke_stiffness, oblique_equals_hooke_stiffness_up_to_lever_arm,
    voigt_normal_feeds_stock_tangential, whole_contact_equals_parts, restitution_and_contact_time,
    bad_values_are_named, wall_sliding_turns_to_rolling, combination_runs, two_ranks_match_one,
    linear_bond_with_contact)}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--engine", required=True)
    p.add_argument("--workdir", required=True)
    p.add_argument("--check", required=True, choices=sorted(CHECKS))
    p.add_argument("--combination", choices=sorted(COMBINATIONS), help="for --check combination_runs")
    p.add_argument("--mpiexec", help="for --check two_ranks_match_one")
    args = p.parse_args()
    try:
        CHECKS[args.check](args)
    except (Failure, subprocess.TimeoutExpired) as e:
        print(f"FAIL: {e}")
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    main()
