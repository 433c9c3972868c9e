"""Two bonded spheres under a prescribed motion (decks/bond_motion.in): the
forces AND torques LIGGGHTS reports on both spheres equal the spec's closed
forms every step, to 1e-6 relative.

Sphere 1 (j in the spec) is held, sphere 2 (i) is driven by fix move; the
bond (created at step 1, r0 = r) lies along x, n = (x_2 - x_1)/r. The
tangential and angular history integrates every step from step 1 on, so at
step s the slip, twist and bend are sums over steps 1..s (the creation step
included). rb = lambda min R, A = pi rb^2, J = pi rb^4/2, I = pi rb^4/4,
rc_i = rc_j = r/2, no damping (eta = 0). Claims (docs/models/bond-nonlinear.md):

- shear (sphere 2 translates along y): F_2 = Fn n + Ft with
  Ft = -k_ft A u_t t, u_t = y_2(s) - y_2(0) the accumulated slip, t the unit
  tangent of y (y minus its n part) and Fn = k_fn2 A (r0 - r) the (tiny,
  second-order) virgin tension of the stretched centre line; F_1 = -F_2;
  T_2 = -rc_i n x Ft, T_1 = -rc_j n x Ft (both spheres turn the same way).
  Geometry: |vt| = v cos(phi), phi = y/r0 <= 5e-4, so the true slip differs
  from y by y phi^2/6 <= 4.2e-8 relative (and the re-projection of Ft onto
  the turning tangent plane loses ~ s dphi^2 < 1e-10): below 1e-7.
- twist (sphere 2 spins about the bond axis through its centre): no force,
  T_2 = Tn = -k_tn J theta_n n, T_1 = -Tn, theta_n = sum w dt. Exact
  (n does not move; w is parallel to n, so there is no slip).
- bend (sphere 2 spins about z through its centre): theta_t = sum w dt z,
  Tt = -k_tt I theta_t; the spin also slips the contact point,
  vtr = -(rc_i w_i) x n, so Ft = +k_ft A rc_i |theta_t| y;
  F_2 = Ft, F_1 = -Ft, T_2 = -rc_i n x Ft + Tt, T_1 = -rc_j n x Ft - Tt.
  Exact (the centres do not move).
- twist-reversal, bend-reversal (and -reset: historyReset on): the twist or
  the bend reversed through zero to the other side (past the first
  extreme's size) and back past the first extreme, in three runs
  (decks/bond_motion_reversal.in); ku and kc of the torque laws differ from
  k. The torque is the signed two-sided law of the accumulated angle phi:
  f(phi) = h(phi; phi_max) for phi >= 0, -h(-phi; -phi_min) below, with
  h(x; x_max) = k x (x >= x_max), ku x + (k - ku) x_max (c x_max <= x),
  -kc x (below), c = (ku - k)/(ku + kc), the extremes updated before the
  law; with historyReset on, phi_min is forgotten while phi > 0 and phi_max
  while phi < 0. Every branch on both sides is visited.
- cycle (sphere 2 moves along x: compression, unloading through the
  negative-stiffness branches into tension, reloading into compression past
  the first peak): F_2 = Fn(d; dmax, dmin) n with the six-branch law,
  d = r0 - r, history updated before the law each step (dmin <= d <= dmax),
  F_1 = -F_2, no torque; every one of the six branches is visited. Exact
  along the axis; Fn crosses zero on the unloading lines, so the force
  error is measured against 1e-6 |Fn| + 1e-10 max|Fn| (d = r0 - r from
  17-digit positions carries ~1e-13 relative round-off).

The stiffnesses of shear, twisting and bending differ (k_ft, k_tn, k_tt
below) so an exchanged one fails the test.

usage: check_bond_motion.py --mode MODE --engine EXE --workdir DIR
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, main, run_ok  # noqa: E402

RELATIVE_TOLERANCE = 1e-6
DT = 1e-6

PARAMS = {
    "diameter": 2e-3,
    "lambda": 0.5,
    "k_fn1": 1e9, "ku_fn1": 2e9, "kc_fn1": 5e8,
    "k_fn2": 1e9, "ku_fn2": 2e9, "kc_fn2": 5e8,
    "k_ft": 4e8,
    "k_tn": 3e8,
    "k_tt": 2e8,
    "nrun": 1000,
}
MODES = {
    # 1e-9 m per step, 1e-6 m (phi = 5e-4) after 1000 steps
    "shear": {"motion": "shear", "vshear": 1e-3},
    # 2 pi / 100 rad/s: 6.3e-5 rad per step
    "twist": {"motion": "twist", "period": 100.0},
    "bend": {"motion": "bend", "period": 100.0},
    # 1e-6 m initial amplitude, 2000 steps per period, 1.25 periods
    "cycle": {"motion": "cycle", "acycle": 1e-6, "tcycle": 2e-3, "nrun": 2500},
}
# 1000 steps forwards, 2500 back, 3500 forwards (decks/bond_motion_reversal.in)
TORQUE_LOOPS = {"ku_tn": 8e8, "kc_tn": 2e8, "ku_tt": 6e8, "kc_tt": 1e8}
for _dof, _axis in (("twist", {"ax": 1.0, "ay": 0.0, "az": 0.0}), ("bend", {"ax": 0.0, "ay": 0.0, "az": 1.0})):
    for _suffix, _hr in (("", "off"), ("-reset", "on")):
        MODES[f"{_dof}-reversal{_suffix}"] = {"motion": _dof, "reversal": 1, "period": 100.0, "nrun": 7000, "n1": 1000,
                                              "hr": _hr, **_axis, **TORQUE_LOOPS}
LOOP_BRANCHES = ("virgin", "unloading", "reverse")
BRANCHES = ("virgin tension", "tension unloading", "tension reverse",
            "compression reverse", "compression unloading", "virgin compression")


def read_dump(path):
    """[(step, {id: [x y z fx fy fz tqx tqy tqz wx wy wz]})] from the dump;
    a step written again by the setup of the next run is kept once (the
    force pass's frame)."""
    frames = []
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            natoms = int(lines[k + 3])
            atoms = {}
            for line in lines[k + 9:k + 9 + natoms]:
                v = line.split()
                atoms[int(v[0])] = [float(c) for c in v[1:]]
            if not frames or step > frames[-1][0]:
                frames.append((step, atoms))
            k += 9 + natoms
        else:
            k += 1
    return frames


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def scale(s, a):
    return [s * x for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def section(p):
    rb = p["lambda"] * p["diameter"] / 2
    return math.pi * rb ** 2, math.pi * rb ** 4 / 2, math.pi * rb ** 4 / 4


def normal_law(d, dmax, dmin, p):
    """(branch, Fn > 0 repulsive): the six-branch law of the spec."""
    area = section(p)[0]
    dc1 = ((p["ku_fn1"] - p["k_fn1"]) / (p["ku_fn1"] + p["kc_fn1"])) ** 2 * dmax
    dc2 = (p["ku_fn2"] - p["k_fn2"]) / (p["ku_fn2"] + p["kc_fn2"]) * dmin
    if d <= dmin:
        return 0, p["k_fn2"] * area * d
    if d < dc2:
        return 1, p["ku_fn2"] * area * d + (p["k_fn2"] - p["ku_fn2"]) * area * dmin
    if d < 0:
        return 2, -p["kc_fn2"] * area * d
    if d < dc1:
        return 3, -p["kc_fn1"] * area * math.sqrt(d)
    if d < dmax:
        return 4, p["ku_fn1"] * area * math.sqrt(d) + (p["k_fn1"] - p["ku_fn1"]) * area * math.sqrt(dmax)
    return 5, p["k_fn1"] * area * math.sqrt(d)


def verify_cycle(frames, p):
    """The cycle: (message, worst relative error)."""
    if len(frames) < p["nrun"] + 1:
        raise Failure(f"only {len(frames)} dump frames for {p['nrun']} steps")
    samples = []
    r0 = None
    dmax = dmin = 0.0
    for step, atoms in frames:
        a1, a2 = atoms[1], atoms[2]
        if step == 0:
            continue
        d = sub(a2[0:3], a1[0:3])
        r = norm(d)
        if step == 1:
            r0 = r
        delta = r0 - r
        dmax, dmin = max(delta, dmax), min(delta, dmin)
        branch, fn = normal_law(delta, dmax, dmin, p)
        samples.append((step, delta, branch, fn, scale(1 / r, d), r, a1, a2))
    peak = max(abs(s[3]) for s in samples)
    worst = 0.0
    visits = [0] * len(BRANCHES)
    for step, delta, branch, fn, n, r, a1, a2 in samples:
        visits[branch] += 1
        f2 = scale(fn, n)
        limit = RELATIVE_TOLERANCE * abs(fn) + 1e-10 * peak
        for name, got, want in (("F_1", a1[3:6], scale(-1, f2)), ("F_2", a2[3:6], f2)):
            err = max(abs(x - y) for x, y in zip(got, want))
            if err > limit:
                raise Failure(f"step {step} (delta={delta:.9g}, {BRANCHES[branch]}): {name} = {got!r}, "
                              f"the closed form gives {want!r}")
            if abs(fn) > 0.0:
                worst = max(worst, err / abs(fn))
        for name, got in (("T_1", a1[6:9]), ("T_2", a2[6:9])):
            if norm(got) > RELATIVE_TOLERANCE * peak * r:
                raise Failure(f"step {step}: {name} = {got}, expected zero")
    if min(visits) < 5:
        raise Failure(f"steps per branch {dict(zip(BRANCHES, visits))}: the cycle misses a branch")
    return f"closed form matched on {len(samples)} steps, steps per branch " \
           f"{dict(zip(BRANCHES, visits))}", worst


class SignedLaw:
    """The signed two-sided torque law of one angle (see the module text)."""

    def __init__(self, k, ku, kc, reset):
        self.k, self.ku, self.kc, self.reset = k, ku, kc, reset
        self.max = self.min = 0.0

    def loop(self, x, x_max):
        c = (self.ku - self.k) / (self.ku + self.kc)
        if x >= x_max:
            return 0, self.k * x
        if x >= c * x_max:
            return 1, self.ku * x + (self.k - self.ku) * x_max
        return 2, -self.kc * x

    def value(self, phi):
        """(side, branch, f(phi)) after updating the history with phi."""
        if self.reset:
            if phi > 0:
                self.min = 0.0
            if phi < 0:
                self.max = 0.0
        self.max, self.min = max(self.max, phi), min(self.min, phi)
        if phi >= 0:
            branch, h = self.loop(phi, self.max)
            return "+", branch, h
        branch, h = self.loop(-phi, -self.min)
        return "-", branch, -h


def expected(mode, p, step, a1, a2, start, r0, spin, value=None):
    """(F_1, F_2, T_1, T_2) of the closed form at this step; `spin` is the
    accumulated rotation angle of sphere 2 (sum of w dt, steps 1..s)."""
    area, polar, inertia = section(p)
    d = sub(a2[0:3], a1[0:3])
    r = norm(d)
    n = scale(1 / r, d)
    rc = r / 2
    if mode == "shear":
        fn = p["k_fn2"] * area * (r0 - r)          # virgin tension: r >= r0
        ey = [0.0, 1.0, 0.0]
        t = sub(ey, scale(dot(ey, n), n))
        t = scale(1 / norm(t), t)
        slip = a2[1] - start[1]
        ft = scale(-p["k_ft"] * area * slip, t)
        f2 = add(scale(fn, n), ft)
        return scale(-1, f2), f2, scale(-rc, cross(n, ft)), scale(-rc, cross(n, ft))
    # the torque law's value: the signed loop's, or virgin loading
    bend = p["k_tt"] * spin if value is None else value
    twist = p["k_tn"] * spin if value is None else value
    if mode == "twist":
        tn = scale(-twist * polar, n)
        zero = [0.0, 0.0, 0.0]
        return zero, zero, scale(-1, tn), tn
    if mode == "bend":
        tt = [0.0, 0.0, -bend * inertia]
        ft = [0.0, p["k_ft"] * area * rc * spin, 0.0]
        shear_torque = scale(-rc, cross(n, ft))
        return scale(-1, ft), ft, sub(shear_torque, tt), add(shear_torque, tt)
    raise ValueError(mode)


def verify(frames, mode, p):
    """Compares every step with the closed form; returns (message, worst
    relative error). Each vector is compared component-wise against
    1e-6 |expected vector|; a vector expected to be zero (twist forces) must
    be below 1e-6 |T| / rc."""
    if len(frames) < p["nrun"] + 1:
        raise Failure(f"only {len(frames)} dump frames for {p['nrun']} steps")
    start = frames[0][1][2]
    r0 = None
    spin = 0.0
    worst = 0.0
    checked = 0
    names = ("F_1", "F_2", "T_1", "T_2", "(T_1+T_2)/2", "(T_2-T_1)/2")
    reversal = mode.endswith(("-reversal", "-reversal-reset"))
    kind = mode.split("-")[0]
    law = None
    if reversal:
        dof = "tn" if kind == "twist" else "tt"
        law = SignedLaw(p["k_" + dof], p["ku_" + dof], p["kc_" + dof], mode.endswith("-reset"))
        # the angle crosses zero as a difference of sums of 1e3 steps: near
        # zero a load is compared against the round-off of that sum (1e-10
        # of the largest torque, 1.5 x the first extreme, and of its shear
        # force) instead of its own size
        moment = section(p)[1 if kind == "twist" else 2]
        peak_angle = 1.5 * p["n1"] * DT * 2 * math.pi / p["period"]
        floor = 1e-10 * max(p["k_" + dof], p["ku_" + dof], p["kc_" + dof]) * moment * peak_angle
    visited = set()
    for step, atoms in frames:
        a1, a2 = atoms[1], atoms[2]
        if step == 0:
            continue
        if step == 1:
            r0 = norm(sub(a2[0:3], a1[0:3]))
        w = a2[9:12]
        if kind in ("twist", "bend"):
            axis = [1.0, 0.0, 0.0] if kind == "twist" else [0.0, 0.0, 1.0]
            if norm(sub(w, scale(dot(w, axis), axis))) != 0.0 or dot(w, axis) == 0.0 or \
                    (dot(w, axis) < 0.0 and not reversal):
                raise Failure(f"step {step}: omega of sphere 2 is {w}, not a spin about {axis}")
            if a1[9:12] != [0.0, 0.0, 0.0]:
                raise Failure(f"step {step}: the held sphere spins: {a1[9:12]}")
            spin += dot(w, axis) * DT
        value = None
        if law:
            side, branch, value = law.value(spin)
            visited.add((side, LOOP_BRANCHES[branch]))
        want = expected(kind, p, step, a1, a2, start, r0, spin, value)
        got = (a1[3:6], a2[3:6], a1[6:9], a2[6:9])
        # the halves of the torque sum and difference: the shear couple
        # -rc n x Ft and the bond torque Tn + Tt on their own, so a small
        # bending torque is not hidden under a large shear couple
        got += (scale(0.5, add(got[2], got[3])), scale(0.5, sub(got[3], got[2])))
        want += (scale(0.5, add(want[2], want[3])), scale(0.5, sub(want[3], want[2])))
        rc = norm(sub(a2[0:3], a1[0:3])) / 2
        torque_scale = max(norm(want[2]), norm(want[3]))
        for name, g, e in zip(names, got, want):
            size = norm(e)
            if size == 0.0:
                limit = RELATIVE_TOLERANCE * torque_scale / (rc if name.startswith("F") else 1.0)
                if norm(g) > limit:
                    raise Failure(f"step {step}: {name} = {g}, expected zero (limit {limit:.3g})")
                continue
            err = max(abs(x - y) for x, y in zip(g, e)) / size
            if law:
                allowed = floor / (rc if name.startswith("F") else 1.0)
                if size > 1e6 * allowed:
                    worst = max(worst, err)
                err = max(0.0, max(abs(x - y) for x, y in zip(g, e)) - allowed) / size
            else:
                worst = max(worst, err)
            if err > RELATIVE_TOLERANCE:
                raise Failure(f"step {step}: {name} = {g!r}, the closed form gives {e!r} "
                              f"(relative error {err:.3g})")
        checked += 1
    if checked < p["nrun"]:
        raise Failure(f"only {checked} steps checked")
    if law and len(visited) < 6:
        raise Failure(f"branches visited {sorted(visited)}: the reversal misses a branch of a side")
    last = frames[-1][1]
    return f"closed form matched on {checked} steps (F and T of both spheres), final " \
           f"F_2 {last[2][3:6]}, T_2 {last[2][6:9]}", worst


def check_run(engine, mode, workdir):
    p = dict(PARAMS)
    variables = {k: v for k, v in PARAMS.items() if not k.startswith(("ku_", "kc_"))}
    variables.update(MODES[mode])
    variables["out"] = "motion.dump"
    run_ok([engine], "bond_motion.in", workdir, variables)
    frames = read_dump(os.path.join(workdir, "motion.dump"))
    p.update(variables)
    message, worst = verify_cycle(frames, p) if mode == "cycle" else verify(frames, mode, p)
    print(f"{mode}: {message}; worst relative error {worst:.3g}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=sorted(MODES), required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check_run(a.engine, a.mode, a.workdir))
