"""Validation of granbond against published DEM benchmarks and closed forms
(Python 3 stdlib only). One case per mode; docs/validation.md derives every
closed form (tests/validation/closed_forms.py) and shows the figures
(docs/validation/make-figures.sh reruns these modes with --json).

    check_validation.py --mode MODE --workdir DIR [--liggghts EXE] [--lammps EXE] [--json FILE]

Modes:
  normal      Chung & Ooi (2011) test 3 (aluminium oxide sphere, 3.9 m/s):
              restitution and contact time against the target restitution,
              on a wall and between two spheres, attraction allowed and
              noAttraction (LIGGGHTS: wall/gran plane and a pair; LAMMPS:
              a pair and a non-integrated 1000 R sphere as the wall).
  oblique     Chung & Ooi test 4 (3.9 m/s, incidence 5..85 deg, mu 0.092):
              tangential restitution, rebound spin, contact-point rebound
              angle, checked where the contact slides throughout.
  spinning    two equal spheres spinning about one axis collide head on
              (Chung & Ooi test 7 type): sideways speed and final spin in
              gross sliding.
  tangential  the no-slip linear tangential spring (Thornton et al.):
              contact-point tangential velocity after/before against kt/kn.
  rolling     Ai et al. (2011), LIGGGHTS plane: a rolling sphere decelerates
              at 5/7 mu_r g and stops at 7 v0^2/(10 mu_r g); on an incline it
              stays if tan(alpha) < mu_r, else rolls at 5/7 g (sin - mu_r cos).
  spindown    spin-down on a frictionless plane (LIGGGHTS plane; LAMMPS on a
              non-integrated equal sphere), the cap alone, eta_r alone, both.
  hertz       comparison, not a check of granbond: LIGGGHTS's stock
              `model hertz` on Chung & Ooi tests 1 (glass spheres) and 2
              (aluminium alloy sphere on a plane) beside voigt with the
              linear stiffness that reaches Hertz's maximum overlap; voigt
              is checked against its closed form, Hertz only reported.
  cantilever  the static bonded cantilever (LIGGGHTS) against the lumped
              beam and Euler-Bernoulli + Timoshenko.
  beam-frequency  the first bending frequency of the clamped bonded beam
              (LIGGGHTS and LAMMPS) against the lumped beam and
              Euler-Bernoulli.
  chain-waves the axial modes of a free bonded chain (LAMMPS, compression
              linearised by compression_linear_below) against the lattice
              dispersion relation; phase velocity against k.

Every tolerance is derived in the function that applies it (time step,
contact onset on the step grid, rolling-spring wind-up).
"""

import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
sys.path.insert(0, HERE)

import closed_forms as cf  # noqa: E402
import deck_runner  # noqa: E402
from deck_runner import Failure, read_table  # noqa: E402

DECKS = os.path.join(HERE, "decks")

# Chung & Ooi (2011), tests 3 and 4: aluminium oxide sphere on a plane 1000x stiffer
AL_OXIDE = dict(radius=2.5e-3, density=4000.0, E=3.8e11, nu=0.23, v=3.9)
WALL_COLUMNS = "step x z vx vz wy fx fz ty".split()
PAIR_COLUMNS = "step x1 x2 v1x v1y v2x v2y w1z w2z f f_t".split()


class Case:
    """Collects measured against expected values; fails at the end."""

    def __init__(self, name):
        self.name = name
        self.rows = []
        self.failures = []
        self.series = {}

    def compare(self, label, measured, expected, tol, checked=True):
        ok = abs(measured - expected) <= tol
        status = "ok" if ok else "OUT"
        if not checked:
            status = "shown"
        print(f"{status:5} {label}: measured {measured:.6g}, expected {expected:.6g}, "
              f"|diff| {abs(measured - expected):.3g}, tol {tol:.3g}")
        self.rows.append(dict(label=label, measured=measured, expected=expected, tol=tol, checked=checked))
        if checked and not ok:
            self.failures.append(f"{label}: measured {measured:.6g}, expected {expected:.6g} +- {tol:.3g}")

    def add(self, series, **point):
        self.series.setdefault(series, []).append(point)

    def finish(self, json_path):
        if json_path:
            with open(json_path, "w", encoding="utf-8") as f:
                json.dump(dict(case=self.name, rows=self.rows, series=self.series), f, indent=1)
        if self.failures:
            raise Failure(f"{len(self.failures)} of {sum(r['checked'] for r in self.rows)} checks out of "
                          "tolerance:\n  " + "\n  ".join(self.failures))
        print(f"{self.name}: {sum(r['checked'] for r in self.rows)} checks within tolerance")


def run(command, deck, workdir, variables, tag, columns):
    variables = dict(variables, out=f"{tag}.txt")
    deck_runner.DECKS = DECKS
    rc, text = deck_runner.run_deck([command], deck, workdir, variables, log=f"log.{tag}")
    if rc != 0:
        raise Failure(f"{deck} ({tag}) exited with {rc}:\n{text[-3000:]}")
    return [dict(zip(columns, r)) for r in read_table(os.path.join(workdir, f"{tag}.txt"))]


def fmt(x):
    return repr(float(x))


# --- engines behind one interface -----------------------------------------
#
# A "wall" impact: sphere of radius R moving towards a plane (LIGGGHTS
# wall/gran) or towards a non-integrated sphere of radius 1000 R (LAMMPS:
# the normal turns by at most the tangential travel over 1000 R during a
# contact, below 1e-5 rad here). Both return the final normal and tangential
# velocity, the spin about the axis the tangential motion turns, the number
# of steps with a normal force, and the force samples.

def voigt_words_liggghts(rolling):
    return "model voigt tangential voigt" + (" rolling_friction voigt" if rolling else "")


def liggghts_wall(a, tag, *, radius, density, vn, vt=0.0, w=0.0, kn, gn=0.0, kt=0.0, gt=0.0, mu=0.0,
                  attraction=False, dt, nrun, gap_steps=3, every=1, z0=None, g=0.0, slope=0.0,
                  rolling=None, models=None, extra=None):
    v = dict(radius=radius, density=density, vz=-vn, vx=vt, wy=w, kn=kn, gn=gn, kt=kt, gt=gt, mu=mu,
             dt=dt, nrun=nrun, every=every)
    v["z0"] = z0 if z0 is not None else radius + gap_steps * vn * dt
    v["settings"] = "noAttraction off" if attraction else "noAttraction on"
    if g > 0:
        v.update(g=g, gx=math.sin(slope), gz=-math.cos(slope))
    if rolling:
        v.update(kr=rolling["kr"], gr=rolling["gr"], mur=rolling["mur"], er=rolling["er"])
    v["models"] = models or voigt_words_liggghts(bool(rolling))
    if models:
        v["settings"] = ""
    v.update(extra or {})
    rows = run(a.liggghts, "liggghts_wall.in", a.workdir, v, tag, WALL_COLUMNS)
    return dict(rows=rows, vn=rows[-1]["vz"], vt=rows[-1]["vx"], w=rows[-1]["wy"],
                steps=sum(1 for r in rows if r["fz"] != 0.0), force=[r["fz"] for r in rows],
                gap=[r["z"] - radius for r in rows])


def lammps_coeffs(kn, gn, kt, gt, mu, attraction, rolling=None):
    words = f"voigt {fmt(kn)} {fmt(gn)} {fmt(kt)} {fmt(gt)} {fmt(mu)} noattraction {'no' if attraction else 'yes'}"
    if rolling:
        words += f" rolling {fmt(rolling['kr'])} {fmt(rolling['gr'])} {fmt(rolling['mur'])} {fmt(rolling['er'])}"
    return words


def lammps_wall(a, tag, *, radius, density, vn, vt=0.0, w=0.0, kn, gn=0.0, kt=0.0, gt=0.0, mu=0.0,
                attraction=False, dt, nrun, gap_steps=3, every=1):
    v = dict(coeffs=lammps_coeffs(kn, gn, kt, gt, mu, attraction), r1=1000 * radius, r2=radius,
             density=density, gap=gap_steps * vn * dt, frozen=1, v2x=-vn, v2y=vt, w2z=w, dt=dt,
             nrun=nrun, every=every)
    rows = run(a.lammps, "lammps_pair.in", a.workdir, v, tag, PAIR_COLUMNS)
    return dict(rows=rows, vn=rows[-1]["v2x"], vt=rows[-1]["v2y"], w=rows[-1]["w2z"],
                steps=sum(1 for r in rows if r["f"] != 0.0), force=[r["f"] for r in rows],
                gap=[r["x2"] - radius for r in rows], curvature=1.0 / (1001 * radius))


def liggghts_pair(a, tag, *, radius, density, v1=(0.0, 0.0), v2=(0.0, 0.0), w1=0.0, w2=0.0, kn, gn=0.0,
                  kt=0.0, gt=0.0, mu=0.0, attraction=False, dt, nrun, gap=0.0, models=None, extra=None):
    v = dict(radius=radius, density=density, v1x=v1[0], v1y=v1[1], v2x=v2[0], v2y=v2[1], w1z=w1, w2z=w2,
             kn=kn, gn=gn, kt=kt, gt=gt, mu=mu, dt=dt, nrun=nrun, gap=gap)
    v["models"] = models or "model voigt tangential voigt"
    v["settings"] = "" if models else ("noAttraction off" if attraction else "noAttraction on")
    v.update(extra or {})
    rows = run(a.liggghts, "liggghts_pair.in", a.workdir, v, tag, PAIR_COLUMNS)
    return rows


def lammps_pair(a, tag, *, radius, density, v1=(0.0, 0.0), v2=(0.0, 0.0), w1=0.0, w2=0.0, kn, gn=0.0,
                kt=0.0, gt=0.0, mu=0.0, attraction=False, dt, nrun, gap=0.0, frozen=0, g=0.0, r1=None,
                rolling=None):
    v = dict(coeffs=lammps_coeffs(kn, gn, kt, gt, mu, attraction, rolling), r1=r1 or radius, r2=radius,
             density=density, v1x=v1[0], v1y=v1[1], v2x=v2[0], v2y=v2[1], w1z=w1, w2z=w2, dt=dt,
             nrun=nrun, gap=gap, frozen=frozen, g=g)
    return run(a.lammps, "lammps_pair.in", a.workdir, v, tag, PAIR_COLUMNS)


def pair_result(rows, every=1):
    last = rows[-1]
    return dict(rel_vn=last["v2x"] - last["v1x"], steps=every * sum(1 for r in rows if r["f"] != 0.0),
                rows=rows)


def engines(a):
    out = []
    if a.liggghts:
        out.append("liggghts")
    if a.lammps:
        out.append("lammps")
    if not out:
        raise Failure("give --liggghts and/or --lammps")
    return out


# --- shared numbers of the impact cases -----------------------------------

def al_oxide():
    m = cf.sphere_mass(AL_OXIDE["radius"], AL_OXIDE["density"])
    e_star = cf.hertz_effective_modulus(AL_OXIDE["E"], AL_OXIDE["nu"], 1000 * AL_OXIDE["E"], AL_OXIDE["nu"])
    kn = cf.linear_stiffness_matching_hertz(m, AL_OXIDE["radius"], e_star, AL_OXIDE["v"])
    return m, kn


def step_for(kn, m_eff, per_half_period=1000):
    """dt with per_half_period steps in the undamped contact (w0 dt = pi/1000)."""
    return math.pi * math.sqrt(m_eff / kn) / per_half_period


def restitution_tolerance(zeta, w0, dt, e):
    """Velocity Verlet is second order while the force is smooth, so a
    contact resolved by w0 dt = pi/1000 loses (w0 dt)^2 of the impulse. The
    force jumps where the dashpot switches on (gamma v0 at the first step)
    and, with attraction, off (-gamma e v0): the contact starts and ends
    between steps, so up to one step of that jump is missed or added, a
    relative impulse error gamma dt / m_eff = 2 zeta w0 dt at each end. With
    noAttraction the force ends at zero (no jump there). Hence
    |e - e_exact| <= 2 zeta w0 dt (1 + e) + 2 (w0 dt)^2."""
    return 2.0 * zeta * w0 * dt * (1.0 + e) + 2.0 * (w0 * dt) ** 2


# --- normal impact ---------------------------------------------------------

def mode_normal(a):
    c = Case("normal")
    m, kn = al_oxide()
    radius, density, v0 = AL_OXIDE["radius"], AL_OXIDE["density"], AL_OXIDE["v"]
    targets = [0.2, 0.4, 0.6, 0.8, 1.0]
    geometries = []
    for eng in engines(a):
        geometries += [(eng, "wall"), (eng, "pair")]
    for eng, geom in geometries:
        m_eff = m if geom == "wall" else m / 2
        dt = step_for(kn, m_eff)
        w0 = math.sqrt(kn / m_eff)
        for attraction in (True, False):
            for e_target in targets:
                zeta = cf.zeta_for_restitution(e_target)
                gn = cf.gamma_n(kn, m_eff, zeta)
                if attraction:
                    e_exact, t_exact = e_target, cf.contact_time_attraction(kn, m_eff, zeta)
                else:
                    e_exact = cf.restitution_no_attraction(zeta)
                    t_exact = cf.contact_time_no_attraction(kn, m_eff, zeta)
                nrun = int(1.25 * t_exact / dt) + 10
                tag = f"{eng}_{geom}_{'attr' if attraction else 'noattr'}_{e_target}"
                kw = dict(radius=radius, density=density, kn=kn, gn=gn, attraction=attraction, dt=dt, nrun=nrun)
                if geom == "wall":
                    fn = liggghts_wall if eng == "liggghts" else lammps_wall
                    r = fn(a, tag, vn=v0, **kw)
                    e, steps = r["vn"] / v0, r["steps"]
                else:
                    fn = liggghts_pair if eng == "liggghts" else lammps_pair
                    r = pair_result(fn(a, tag, v2=(-v0, 0.0), gap=3 * v0 * dt, **kw))
                    e, steps = r["rel_vn"] / v0, r["steps"]
                label = f"{eng} {geom} {'attraction' if attraction else 'noAttraction'} e_target {e_target}"
                c.compare(f"{label}: e", e, e_exact, restitution_tolerance(zeta, w0, dt, e_exact))
                # the force is nonzero on whole steps only: one step at each end
                c.compare(f"{label}: t_c [s]", steps * dt, t_exact, 2 * dt)
                c.add(f"{eng}_{geom}_{'attr' if attraction else 'noattr'}", e_target=e_target, e=e,
                      e_exact=e_exact, t=steps * dt, t_exact=t_exact, t0=math.pi / w0)
    c.finish(a.json)


# --- oblique impact ----------------------------------------------------------

def mode_oblique(a):
    c = Case("oblique")
    m, kn = al_oxide()
    radius, density, v0 = AL_OXIDE["radius"], AL_OXIDE["density"], AL_OXIDE["v"]
    mu, e_n = 0.092, 0.98
    zeta = cf.zeta_for_restitution_no_attraction(e_n)
    gn = cf.gamma_n(kn, m, zeta)
    # kt/kn = 2/7 gives the tangential and normal oscillations one frequency;
    # gamma_t in the same ratio. Sliding from the first step needs
    # kt tan(theta) > mu kn, i.e. tan(theta) > 0.322: below the gross-sliding
    # threshold 3.5 mu (1 + e) = 0.638 (32.5 deg), so above it the contact
    # slides throughout.
    kt, gt = 2.0 / 7.0 * kn, 2.0 / 7.0 * gn
    dt = step_for(kn, m)
    w0 = math.sqrt(kn / m)
    tol_e = restitution_tolerance(zeta, w0, dt, e_n)
    threshold = cf.oblique_sliding_threshold(mu, e_n)
    nrun = int(1.25 * cf.contact_time_no_attraction(kn, m, zeta) / dt) + 10
    for eng in engines(a):
        fn = liggghts_wall if eng == "liggghts" else lammps_wall
        for deg in (5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 75, 80, 85):
            th = math.radians(deg)
            vn, vt = v0 * math.cos(th), v0 * math.sin(th)
            r = fn(a, f"{eng}_oblique_{deg}", radius=radius, density=density, vn=vn, vt=vt, kn=kn, gn=gn,
                   kt=kt, gt=gt, mu=mu, dt=dt, nrun=nrun)
            et = r["vt"] / vt
            spin = r["w"]
            en = r["vn"] / vn
            rebound = math.atan((r["vt"] - radius * spin) / r["vn"])
            et_x, spin_x, reb_x = cf.oblique_gross_sliding(th, v0, radius, mu, e_n)
            sliding = math.tan(th) >= threshold
            # Tangential impulse = mu x normal impulse on every step of gross
            # sliding, so the tangential errors are those of the normal
            # impulse (tol_e of the normal restitution) times mu / tan(theta)
            # (e_t), 5 mu v_n / 2R (spin) and 3.5 mu / e (tan of the angle).
            # LAMMPS's wall is a sphere of 1000 R: over the contact the normal
            # turns by phi = vt t_c / (1001 R), tilting the normal impulse
            # (1 + e) m vn by phi into the tangential direction.
            # The same tilt mixes vt phi into the normal velocity, so the
            # normal approach speed, hence the normal impulse, and the x
            # velocity read as normal are each off by up to vt phi.
            phi = vt * r["steps"] * dt * r.get("curvature", 0.0)
            tol_et = mu * tol_e / math.tan(th) + (1.0 + e_n) * vn * phi / vt + 1e-12
            tol_en = tol_e + 2 * vt * phi / vn
            tol_spin = 2.5 * mu * (tol_e * vn + (1.0 + e_n) * vt * phi) / radius + 1e-9
            label = f"{eng} {deg} deg"
            c.compare(f"{label}: e_n", en, e_n, tol_en, sliding)
            c.compare(f"{label}: e_t", et, et_x, tol_et, sliding)
            c.compare(f"{label}: spin [rad/s]", spin, spin_x, tol_spin, sliding)
            tol_angle = (3.5 * mu + abs(math.tan(reb_x))) * tol_e / e_n
            c.compare(f"{label}: rebound angle [deg]", math.degrees(rebound), math.degrees(reb_x),
                      math.degrees(tol_angle) + 1e-9, sliding)
            c.add(eng, deg=deg, et=et, spin=spin, rebound=math.degrees(rebound), et_x=et_x, spin_x=spin_x,
                  rebound_x=math.degrees(reb_x), sliding=sliding)
    c.add("threshold", deg=math.degrees(math.atan(threshold)))
    c.finish(a.json)


# --- two spinning spheres ----------------------------------------------------

def mode_spinning(a):
    c = Case("spinning")
    m, kn = al_oxide()
    radius, density = AL_OXIDE["radius"], AL_OXIDE["density"]
    # v0 small: the spheres slide past each other by ~2 vy t_c, turning the
    # normal (a geometric effect of order v0 t_c / R relative that the
    # fixed-normal closed form leaves out; see the tolerance below)
    v0, mu, e_n = 0.05, 0.092, 0.98
    m_eff = m / 2
    zeta = cf.zeta_for_restitution_no_attraction(e_n)
    gn = cf.gamma_n(kn, m_eff, zeta)
    kt, gt = 2.0 / 7.0 * kn, 2.0 / 7.0 * gn
    dt = step_for(kn, m_eff)
    w_n = math.sqrt(kn / m_eff)
    tol_e = restitution_tolerance(zeta, w_n, dt, e_n)
    nrun = int(1.25 * cf.contact_time_no_attraction(kn, m_eff, zeta) / dt) + 10
    threshold = cf.spinning_pair_threshold(v0, radius, mu, e_n)
    for eng in engines(a):
        fn = liggghts_pair if eng == "liggghts" else lammps_pair
        for w0 in (2.0, 5.0, 10.0, 15.0, 20.0, 30.0, 50.0, 100.0):
            rows = fn(a, f"{eng}_spin_{w0:g}", radius=radius, density=density, v1=(v0, 0.0), v2=(-v0, 0.0),
                      w1=w0, w2=w0, kn=kn, gn=gn, kt=kt, gt=gt, mu=mu, dt=dt, nrun=nrun, gap=3 * 2 * v0 * dt)
            last = rows[-1]
            side_x, spin_x = cf.spinning_pair_gross_sliding(w0, v0, radius, mu, e_n)
            sliding = w0 >= threshold
            # the sideways impulse is mu x the normal one: its relative error
            # is the normal impulse's, tol_e / (1 + e). And the spheres slide
            # past each other by at most 2 vy t_c during the contact, turning
            # the normal by up to that over 2R: the normal impulse
            # (1 + e) m v0 then has a sideways part of at most that fraction.
            t_c = sum(1 for r in rows if r["f"] != 0.0) * dt
            tol_side = mu * v0 * tol_e + (1.0 + e_n) * v0 * 2 * side_x * t_c / (2 * radius)
            label = f"{eng} w0 {w0:g} rad/s"
            c.compare(f"{label}: vy1 [m/s]", last["v1y"], -side_x, tol_side + 1e-12, sliding)
            c.compare(f"{label}: vy2 [m/s]", last["v2y"], side_x, tol_side + 1e-12, sliding)
            c.compare(f"{label}: w1 [rad/s]", last["w1z"], spin_x, 2.5 * tol_side / radius + 1e-9, sliding)
            c.compare(f"{label}: w2 [rad/s]", last["w2z"], spin_x, 2.5 * tol_side / radius + 1e-9, sliding)
            c.add(eng, w0=w0, vy2=last["v2y"], w1=last["w1z"], w2=last["w2z"], vy_x=side_x, w_x=spin_x,
                  sliding=sliding)
    c.add("threshold", w0=threshold)
    c.finish(a.json)


# --- no-slip tangential spring ---------------------------------------------

def mode_tangential(a):
    c = Case("tangential")
    m, kn = al_oxide()
    radius, density, v0 = AL_OXIDE["radius"], AL_OXIDE["density"], 1.0
    vt = 0.1
    dt = step_for(kn, m, 2000)
    w_n = math.sqrt(kn / m)
    nrun = int(1.1 * math.pi / w_n / dt) + 10
    for eng in engines(a):
        fn = liggghts_wall if eng == "liggghts" else lammps_wall
        for ratio in (0.0, 0.05, 0.1, 0.2, 2.0 / 7.0, 0.4, 0.5, 0.6, 0.8, 1.0, 1.2, 1.5):
            r = fn(a, f"{eng}_tangential_{ratio:.4f}", radius=radius, density=density, vn=v0, vt=vt, kn=kn,
                   kt=ratio * kn, mu=1e6, dt=dt, nrun=nrun)
            measured = (r["vt"] - radius * r["w"]) / vt
            expected = cf.tangential_ratio_no_slip(ratio)
            w_t = math.sqrt(3.5 * ratio * kn / m)
            # The spring starts on the step grid, up to one step away from the
            # normal contact's true start, and the contact ends on it too: a
            # phase error of at most w_t dt at each end of the tangential
            # oscillation, plus the second-order error of both oscillators.
            tol = 2.0 * w_t * dt + 2.0 * ((w_n + w_t) * dt) ** 2
            c.compare(f"{eng} kt/kn {ratio:.4f}: v_t after/before", measured, expected, tol)
            c.add(eng, ratio=ratio, measured=measured, expected=expected)
    c.finish(a.json)


# --- rolling resistance ------------------------------------------------------

SEED = dict(radius=1.0e-3, density=2500.0, kn=1.0e4, gn=0.05, kt=6.0e3, gt=1.0e-3, mu=0.5)
ROLL = dict(kr=1.0e-4, gr=1.0e-8, mur=0.05, er=0.0)


def seed_numbers():
    m = cf.sphere_mass(SEED["radius"], SEED["density"])
    return m, cf.sphere_inertia(SEED["radius"], SEED["density"])


def fit_slope(ts, ys):
    n = len(ts)
    mt, my = sum(ts) / n, sum(ys) / n
    return sum((t - mt) * (y - my) for t, y in zip(ts, ys)) / sum((t - mt) ** 2 for t in ts)


def resting_wall(a, tag, *, vx=0.0, wy=0.0, rolling, mu, slope=0.0, dt, nrun, every):
    m, _ = seed_numbers()
    z0 = SEED["radius"] - m * cf.G * math.cos(slope) / SEED["kn"]
    return liggghts_wall(a, tag, radius=SEED["radius"], density=SEED["density"], vn=0.0, vt=vx, w=wy,
                         kn=SEED["kn"], gn=SEED["gn"], kt=SEED["kt"], gt=SEED["gt"], mu=mu, dt=dt, nrun=nrun,
                         every=every, z0=z0, g=cf.G, slope=slope, rolling=rolling)["rows"]


def mode_rolling(a):
    c = Case("rolling")
    if not a.liggghts:
        raise Failure("rolling needs --liggghts (a plane wall)")
    m, _ = seed_numbers()
    radius, dt, every = SEED["radius"], 1.0e-6, 50
    cap = ROLL["mur"] * m * cf.G * radius
    theta_cap = cap / ROLL["kr"]
    # 1. a sphere launched rolling
    v0 = 0.03
    a_x = -cf.rolling_deceleration(ROLL["mur"])
    t_stop = v0 / a_x
    x_stop = v0**2 / (2 * a_x)
    rows = resting_wall(a, "roll_stop", vx=v0, wy=v0 / radius, rolling=ROLL, mu=SEED["mu"], dt=dt,
                        nrun=int(1.3 * t_stop / dt), every=every)
    window = [r for r in rows if 0.1 * t_stop <= r["step"] * dt <= 0.8 * t_stop]
    decel = -fit_slope([r["step"] * dt for r in window], [r["vx"] for r in window])
    # The torque reaches the cap after the rolling spring winds up by
    # theta_cap = mu_r Fn R / k_r, i.e. after theta_cap R / v0; the
    # deceleration in the window is then the cap's. What is left: the
    # tangential and rolling springs carry f = m a and the cap torque at a
    # constant wind-up, so no error of the order of dt remains; the
    # tolerance 1e-4 relative covers the normal force's settling
    # (the sphere starts at the static overlap m g / kn).
    c.compare("rolling sphere: deceleration [m/s^2]", decel, a_x, 1e-4 * a_x)
    x_final = rows[-1]["x"]
    # Stop point: the wind-up delays the full cap by theta_cap R / v0 (half
    # of it lost on average: v0 theta_cap R / (2 v0) = theta_cap R / 2), and
    # after the stop the rolling spring gives back at most its wind-up,
    # R theta_cap: tol = 1.5 R theta_cap + v0 dt.
    c.compare("rolling sphere: stop distance [m]", x_final, x_stop, 1.5 * radius * theta_cap + v0 * dt)
    c.add("roll", t=[r["step"] * dt for r in rows], vx=[r["vx"] for r in rows], x=[r["x"] for r in rows],
          a=a_x, v0=v0, x_stop=x_stop)
    # 2. the incline: tilted gravity on a horizontal plane
    for ratio in (0.5, 0.9, 1.1, 2.0, 4.0):
        slope = math.atan(ratio * ROLL["mur"])
        t_run = 0.02
        rows = resting_wall(a, f"incline_{ratio}", rolling=ROLL, mu=SEED["mu"], slope=slope, dt=dt,
                            nrun=int(t_run / dt), every=every)
        expected = max(0.0, cf.rolling_deceleration(ROLL["mur"], slope))
        window = [r for r in rows if r["step"] * dt >= 0.25 * t_run]
        acc = fit_slope([r["step"] * dt for r in window], [r["vx"] for r in window])
        travel = max(abs(r["x"]) for r in rows)
        label = f"incline tan(alpha)/mu_r = {ratio}"
        if ratio < 1.0:
            # Staying: the static friction f = m g sin(alpha) and the torque
            # f R sit in the springs, displacing the centre by
            # f/kt + f R^2/kr. Released from rest the sphere overshoots to up
            # to twice that load, past the cap when tan(alpha) > mu_r / 2, so
            # it may creep a little at first; then it rocks about a fixed
            # point, damped by gamma_r, with an amplitude below that static
            # displacement: over the second half of the run x stays within
            # 2 (f/kt + f R^2/kr) (rolling would cover a t^2 T/8 there).
            f = m * cf.G * math.sin(slope)
            late = [r["x"] for r in rows if r["step"] * dt >= 0.5 * t_run]
            c.compare(f"{label}: x range over the second half [m]", max(late) - min(late), 0.0,
                      2 * (f / SEED["kt"] + f * radius**2 / ROLL["kr"]))
            c.compare(f"{label}: largest displacement [m]", travel, 0.0, 0.0, checked=False)
        else:
            # Rolling: a constant acceleration after the wind-up; the fit over
            # the last 3/4 of the run is off by the normal force's settling
            # only, as for the rolling sphere: 1e-4 of g sin(alpha).
            c.compare(f"{label}: acceleration [m/s^2]", acc, expected, 1e-4 * cf.G * math.sin(slope))
        c.add("incline", ratio=ratio, acc=acc, expected=expected, travel=travel)
    c.finish(a.json)


def mode_spindown(a):
    c = Case("spindown")
    m, inertia = seed_numbers()
    radius, dt, every = SEED["radius"], 1.0e-6, 20
    w0 = 20.0
    # gamma_r = 0: the rolling dashpot sits inside the cap, and near the stop
    # (w below gamma_r w' / k_r) it lets the spring stick a little before w
    # reaches zero, a delay the closed forms do not describe; without it the
    # capped torque is exact from the wind-up to the stop.
    spin_roll = dict(ROLL, gr=0.0)
    variants = [("cap", spin_roll), ("viscous", dict(spin_roll, mur=0.0, er=2.5e-10)),
                ("both", dict(spin_roll, er=2.5e-10))]
    for eng in engines(a):
        # LIGGGHTS: a plane (R* = R); LAMMPS: a non-integrated equal sphere
        # below (R* = R/2), gravity along the line of centres.
        r_star = radius if eng == "liggghts" else radius / 2
        for name, rolling in variants:
            cap = rolling["mur"] * m * cf.G * r_star
            eta = rolling["er"]
            t_end = 1.5 * (cf.stop_time_with_viscous(w0, cap, eta, inertia) if cap > 0 else 3 * inertia / eta)
            nrun = int(t_end / dt)
            if eng == "liggghts":
                rows = resting_wall(a, f"spin_{name}", wy=w0, rolling=rolling, mu=0.0, dt=dt, nrun=nrun,
                                    every=every)
                ts, ws = [r["step"] * dt for r in rows], [r["wy"] for r in rows]
            else:
                overlap = m * cf.G / SEED["kn"]
                rows = lammps_pair(a, f"lmp_spin_{name}", radius=radius, density=SEED["density"],
                                   w2=w0, kn=SEED["kn"], gn=SEED["gn"], kt=SEED["kt"], gt=SEED["gt"], mu=0.0,
                                   dt=dt, nrun=nrun, gap=-overlap, frozen=1, g=cf.G, rolling=rolling)
                rows = rows[::every]
                ts, ws = [r["step"] * dt for r in rows], [r["w2z"] for r in rows]
            theta_cap = cap / rolling["kr"]
            label = f"{eng} {name}"
            if cap > 0:
                t_x = cf.stop_time_with_viscous(w0, cap, eta, inertia)
                k = next(i for i, w in enumerate(ws) if w <= 0.0)
                t_meas = ts[k - 1] + (ts[k] - ts[k - 1]) * ws[k - 1] / (ws[k - 1] - ws[k])
                # the full cap acts once the rolling spring has wound up by
                # theta_cap (after theta_cap / w0; half that time is lost),
                # and w falls linearly, so the zero crossing interpolated
                # between outputs is exact but for one step dt.
                c.compare(f"{label}: stop time [s]", t_meas, t_x, theta_cap / w0 + dt)
            # w(t) at a quarter and half of the stop time (or of 3 tau)
            t_ref = cf.stop_time_with_viscous(w0, cap, eta, inertia) if cap > 0 else 3 * inertia / eta
            for frac in (0.25, 0.5):
                t = frac * t_ref
                k = min(range(len(ts)), key=lambda i: abs(ts[i] - t))
                w_x = cf.spin_with_viscous(ts[k], w0, cap, eta, inertia)
                # The viscous torque is evaluated with the half-step spin:
                # a relative error of dt/(2 tau) per step, t dt / (2 tau^2)
                # accumulated; the wind-up delay costs cap theta_cap /(2 I w0).
                tau = inertia / eta if eta > 0 else float("inf")
                tol = w0 * (ts[k] * dt / (2 * tau**2) + dt / tau) + cap / inertia * theta_cap / w0 + 1e-9
                c.compare(f"{label}: w at t = {ts[k]:.4g} s [rad/s]", ws[k], w_x, tol)
            c.add(f"{eng}_{name}", t=ts, w=ws, w_x=[cf.spin_with_viscous(t, w0, cap, eta, inertia)
                                                   if cap == 0.0 or t <= t_ref else 0.0 for t in ts])
    c.finish(a.json)


# --- Hertz comparison ------------------------------------------------------

GLASS = dict(radius=0.01, density=2800.0, E=4.8e10, nu=0.2, v=10.0)          # Chung & Ooi test 1
AL_ALLOY = dict(radius=0.1, density=2699.0, E=7.0e10, nu=0.3, v=0.2)        # Chung & Ooi test 2


def mode_hertz(a):
    c = Case("hertz")
    if not a.liggghts:
        raise Failure("hertz needs --liggghts")
    hertz = "model hertz tangential no_history"
    for name, mat, geom in (("glass", GLASS, "pair"), ("aluminium alloy", AL_ALLOY, "wall")):
        m = cf.sphere_mass(mat["radius"], mat["density"])
        if geom == "pair":
            m_eff, r_eff = m / 2, mat["radius"] / 2
            e_star = cf.hertz_effective_modulus(mat["E"], mat["nu"], mat["E"], mat["nu"])
            v_rel = 2 * mat["v"]
        else:
            m_eff, r_eff = m, mat["radius"]
            e_star = cf.hertz_effective_modulus(mat["E"], mat["nu"], 1000 * mat["E"], mat["nu"])
            v_rel = mat["v"]
        d_h, f_h, t_h = cf.hertz_impact(m_eff, r_eff, e_star, v_rel)
        kn = m_eff * v_rel**2 / d_h**2
        d_l, f_l, t_l = d_h, kn * d_h, math.pi * math.sqrt(m_eff / kn)
        dt = t_h / 2000
        nrun = int(1.3 * t_h / dt) + 10
        results = {}
        for model in ("voigt", "hertz"):
            words = None if model == "voigt" else hertz
            extra = dict(E1=mat["E"], nu=mat["nu"], e=1.0, E2=1000 * mat["E"])
            tag = f"hertz_{model}_{geom}"
            if geom == "pair":
                rows = liggghts_pair(a, tag, radius=mat["radius"], density=mat["density"], v1=(mat["v"], 0.0),
                                     v2=(-mat["v"], 0.0), kn=kn, dt=dt, nrun=nrun, gap=3 * v_rel * dt,
                                     models=words, extra=extra)
                overlaps = [2 * mat["radius"] - (r["x2"] - r["x1"]) for r in rows]
                forces = [-r["f"] for r in rows]
            else:
                r = liggghts_wall(a, tag, radius=mat["radius"], density=mat["density"], vn=v_rel, kn=kn, dt=dt,
                                  nrun=nrun, models=words, extra=extra)
                overlaps = [-g for g in r["gap"]]
                forces = r["force"]
            steps = sum(1 for f in forces if f != 0.0)
            results[model] = (max(overlaps), max(forces), steps * dt)
            c.add(f"{geom}_{model}", overlap=[d for d, f in zip(overlaps, forces) if f != 0.0],
                  force=[f for f in forces if f != 0.0])
        d, f, t = results["voigt"]
        # undamped, w0 dt = pi/(2000 t_h/t_l): second order, (w0 dt)^2 relative;
        # the sampled maximum sits up to half a step off the true one:
        # relative (w0 dt)^2 / 8 on overlap and force; t_c: one step each end
        w0dt = math.sqrt(kn / m_eff) * dt
        c.compare(f"{name} voigt: max overlap [m]", d, d_l, 2 * w0dt**2 * d_l)
        c.compare(f"{name} voigt: max force [N]", f, f_l, 2 * w0dt**2 * f_l)
        c.compare(f"{name} voigt: contact time [s]", t, t_l, 2 * dt)
        d, f, t = results["hertz"]
        c.compare(f"{name} LIGGGHTS hertz (comparison): max overlap [m]", d, d_h, 0, checked=False)
        c.compare(f"{name} LIGGGHTS hertz (comparison): max force [N]", f, f_h, 0, checked=False)
        c.compare(f"{name} LIGGGHTS hertz (comparison): contact time [s]", t, t_h, 0, checked=False)
        c.add(f"{geom}_closed", d_h=d_h, f_h=f_h, t_h=t_h, d_l=d_l, f_l=f_l, t_l=t_l, e_star=e_star,
              r_eff=r_eff, kn=kn, m_eff=m_eff, v=v_rel)
    c.finish(a.json)


# --- bonds -------------------------------------------------------------------

BEAM = dict(radius=1.0e-3, density=2500.0, kb=1.0e10, lam=1.0)


def beam_numbers():
    rb = BEAM["lam"] * BEAM["radius"]
    area = math.pi * rb**2
    inertia = math.pi * rb**4 / 4
    a = 2 * BEAM["radius"]
    k_bend = BEAM["kb"] * inertia          # moment per bending angle of one bond
    k_shear = BEAM["kb"] * area            # shear force per shear displacement
    k_axial = BEAM["kb"] * area
    m = cf.sphere_mass(BEAM["radius"], BEAM["density"])
    return a, k_bend, k_shear, k_axial, m


def mode_cantilever(a):
    c = Case("cantilever")
    n, load = 21, 5.0e-5
    spacing, k_bend, k_shear, _, m = beam_numbers()
    nb = n - 1
    rows = run(a.liggghts, "liggghts_beam.in", a.workdir,
               dict(n=n, load=load, damp=2.0e-3, kb=BEAM["kb"], nrun=40000, every=500), "cantilever",
               ["step", "ztip", "zp"])
    tip = -rows[-1]["ztip"]
    discrete = cf.cantilever_tip_discrete(nb, spacing, load, k_bend, k_shear)
    continuum = cf.cantilever_tip_continuum(nb * spacing, load, k_bend * spacing, k_shear * spacing)
    # Static: dt enters only through the settling. fix viscous damps the
    # first mode (120 rad/s) at gamma/2m = 96 1/s: after 0.2 s its amplitude
    # is e^-19 of the initial ~tip, so the tolerance is what the deflection
    # leaves out: the axial shortening of the bonds and the change of lever
    # as the beam bends, both relative (tip/L)^2 = 3e-6, and the bonds'
    # tension from the load's component along them, smaller still: 1e-5.
    c.compare("tip deflection vs lumped beam [m]", tip, discrete, 1e-5 * discrete)
    c.compare("tip deflection vs Euler-Bernoulli + Timoshenko [m]", tip, continuum,
              abs(continuum - discrete) + 1e-5 * discrete)
    # the deflection line
    with open(os.path.join(a.workdir, "final.txt"), encoding="utf-8") as f:
        lines = f.read().split("ITEM: ATOMS")[1].splitlines()[1:]
    pts = sorted((float(x), -float(z)) for _, x, _, z in (l.split() for l in lines if l.strip()))
    c.add("shape", x=[p[0] for p in pts], w=[p[1] for p in pts],
          eb=[load * (x * x * (3 * nb * spacing - x)) / (6 * k_bend * spacing) + load * x / (k_shear * spacing)
              for x, _ in pts])
    c.finish(a.json)


def zero_crossing_frequency(ts, ys):
    """Angular frequency from the first and last upward/downward zero
    crossings (linear interpolation), with the mean removed."""
    mean = sum(ys) / len(ys)
    ys = [y - mean for y in ys]
    crossings = []
    for i in range(1, len(ys)):
        if (ys[i - 1] < 0.0) != (ys[i] < 0.0):
            crossings.append(ts[i - 1] + (ts[i] - ts[i - 1]) * ys[i - 1] / (ys[i - 1] - ys[i]))
    if len(crossings) < 3:
        raise Failure(f"only {len(crossings)} zero crossings")
    return math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0]), len(crossings)


def mode_beam_frequency(a):
    c = Case("beam-frequency")
    n = 21
    spacing, k_bend, k_shear, _, m = beam_numbers()
    nf = n - 1
    w_disc, shape = cf.cantilever_first_frequency_discrete(nf, spacing, m, k_bend, k_shear)
    w_eb = cf.cantilever_first_frequency_continuum(nf * spacing, k_bend * spacing, m / spacing)
    dt = 5.0e-6
    periods = 4
    nrun = int(periods * 2 * math.pi / w_disc / dt)
    # initial velocity along the lumped beam's first mode (an atom-style
    # expression of x: the mode tabulated as a polynomial would be a fit;
    # the static shape x^2 (3L - x) carries 99% of the mode and the rest
    # shifts the crossings by less than the tolerance below, see there)
    length = nf * spacing
    vmax = 1.0e-4
    vz = f"{vmax}*x*x*(3*{length}-x)/(2*{length}^3)"
    for eng in engines(a):
        if eng == "liggghts":
            rows = run(a.liggghts, "liggghts_beam.in", a.workdir,
                       dict(n=n, vz=vz, kb=BEAM["kb"], dt=dt, nrun=nrun, every=1), "beam_free",
                       ["step", "ztip", "zp"])
        else:
            d_eps = 1.0e-6
            coeffs = (f"voigt 1e4 0 0 0 0 bond/nonlinear lambda {BEAM['lam']} "
                      f"k_fn1 {BEAM['kb'] * math.sqrt(d_eps)!r} ku_fn1 {BEAM['kb'] * math.sqrt(d_eps)!r} "
                      f"kc_fn1 {BEAM['kb'] * math.sqrt(d_eps)!r} compression_linear_below {d_eps} "
                      f"k_fn2 {BEAM['kb']} ku_fn2 {BEAM['kb']} kc_fn2 {BEAM['kb']} k_ft {BEAM['kb']} "
                      f"k_tn {BEAM['kb']} ku_tn {BEAM['kb']} kc_tn {BEAM['kb']} "
                      f"k_tt {BEAM['kb']} ku_tt {BEAM['kb']} kc_tt {BEAM['kb']} damping no "
                      "create_distance 2.05e-3 create_step 1 break distance 3.0e-3")
            rows = run(a.lammps, "lammps_chain.in", a.workdir,
                       dict(coeffs=coeffs, n=n, clamp=1, vz=vz, dt=dt, nrun=nrun, every=1), "lmp_beam_free",
                       ["step", "x1", "ztip", "xn"])
        ts = [r["step"] * dt for r in rows]
        w_meas, count = zero_crossing_frequency(ts, [r["ztip"] for r in rows])
        # Tolerance: velocity Verlet's modified frequency, (w dt)^2/24
        # relative (3e-8 here); the higher modes the initial shape excites
        # (< 1% of the amplitude, 6x the frequency and above) move a crossing
        # by at most their share of the amplitude over the mode-1 slope,
        # 0.01/(pi) of a half period at the first and at the last crossing,
        # averaged over the crossings counted; the spheres' rotary inertia
        # left out of the lumped model lowers the frequency by
        # (2/5 R^2) (beta/L)^2 / 2 relative (4.4e-4).
        rotary = 0.4 * BEAM["radius"] ** 2 * (1.8751 / length) ** 2 / 2
        tol = w_disc * ((w_disc * dt) ** 2 / 24 + 2 * 0.01 / math.pi / (count - 1) + rotary)
        c.compare(f"{eng}: first bending frequency vs lumped beam [rad/s]", w_meas, w_disc, tol)
        c.compare(f"{eng}: first bending frequency vs Euler-Bernoulli [rad/s]", w_meas, w_eb, 0, checked=False)
        c.add(eng, t=ts[::20], z=[r["ztip"] for r in rows][::20], w=w_meas)
    c.add("closed", w_disc=w_disc, w_eb=w_eb, n_free=nf)
    c.finish(a.json)


def mode_chain_waves(a):
    c = Case("chain-waves")
    if not a.lammps:
        raise Failure("chain-waves needs --lammps (compression_linear_below)")
    n = 10
    spacing, _, _, _, m = beam_numbers()
    kb = 1.0e9
    lam = 0.5
    area = math.pi * (lam * BEAM["radius"]) ** 2
    k_axial = kb * area
    d_eps = 1.0e-6
    root = kb * math.sqrt(d_eps)
    # linearised compression: k_fn1 A d / sqrt(d_eps) = k_fn2 A d below d_eps,
    # so the bond is one linear spring k_fn2 A on both sides while |d| < d_eps
    coeffs = (f"voigt 1e4 0 0 0 0 bond/nonlinear lambda {lam} k_fn1 {root!r} ku_fn1 {root!r} kc_fn1 {root!r} "
              f"compression_linear_below {d_eps} k_fn2 {kb} ku_fn2 {kb} kc_fn2 {kb} k_ft {kb} "
              f"k_tn {kb} ku_tn {kb} kc_tn {kb} k_tt {kb} ku_tt {kb} kc_tt {kb} damping no "
              "create_distance 2.05e-3 create_step 1 break distance 3.0e-3")
    w_unit = math.sqrt(k_axial / m)
    dt = 1.0e-6
    c0 = spacing * w_unit
    for p in range(1, n):
        w_x = cf.chain_axial_frequency(p, n, k_axial, m)
        # neighbour stretch amplitude (v/w) 2 sin(p pi/2n) = d_eps/4
        vamp = 0.25 * d_eps * w_x / (2 * math.sin(p * math.pi / (2 * n)))
        vx = f"{vamp!r}*cos({p}*PI*(id-0.5)/{n})"
        nrun = int(4 * 2 * math.pi / w_x / dt)
        rows = run(a.lammps, "lammps_chain.in", a.workdir,
                   dict(coeffs=coeffs, n=n, clamp=0, vx=vx, dt=dt, nrun=nrun, every=1), f"chain_p{p}",
                   ["step", "x1", "zn", "xn"])
        ts = [r["step"] * dt for r in rows]
        w_meas, count = zero_crossing_frequency(ts, [r["x1"] for r in rows])
        # The mode is exact for the lattice, so only the integrator remains:
        # velocity Verlet oscillates at its modified frequency
        # 2/dt asin(w dt/2), (w dt)^2/24 above w (relative); the crossings'
        # linear interpolation misplaces the first and the last by at most
        # (w dt)^2/8 of a step, spread over (count - 1) half periods. Against
        # the lattice the tolerance is twice the integrator's shift; against
        # the modified frequency it is the interpolation bound (+ 1e-8 for
        # the %.15g output).
        wdt = w_x * dt
        w_verlet = 2.0 / dt * math.asin(wdt / 2.0)
        interp = w_x * 2 * wdt**2 / 8 * (dt * w_x / math.pi) / (count - 1)
        tol = 2 * (w_verlet - w_x) + interp
        k = p * math.pi / (n * spacing)
        c.compare(f"mode {p}: angular frequency vs lattice [rad/s]", w_meas, w_x, tol)
        c.compare(f"mode {p}: angular frequency vs velocity Verlet on the lattice [rad/s]", w_meas, w_verlet,
                  interp + 1e-8 * w_x)
        c.compare(f"mode {p}: phase velocity [m/s]", w_meas / k, w_x / k, tol / k)
        c.add("modes", p=p, k=k, w=w_meas, w_x=w_x, c=w_meas / k, c_x=w_x / k, c0=c0)
    # the rod limit of mode 1: pi c0 / (n a)
    w_rod = math.pi * c0 / (n * spacing)
    c.compare("mode 1 vs rod theory pi c0 / L [rad/s]", c.series["modes"][0]["w"], w_rod, 0, checked=False)
    c.finish(a.json)


MODES = {"normal": mode_normal, "oblique": mode_oblique, "spinning": mode_spinning,
         "tangential": mode_tangential, "rolling": mode_rolling, "spindown": mode_spindown,
         "hertz": mode_hertz, "cantilever": mode_cantilever, "beam-frequency": mode_beam_frequency,
         "chain-waves": mode_chain_waves}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True, choices=sorted(MODES))
    p.add_argument("--workdir", required=True)
    p.add_argument("--liggghts")
    p.add_argument("--lammps")
    p.add_argument("--json")
    a = p.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    try:
        MODES[a.mode](a)
    except Failure as e:
        print(f"FAIL: {e}")
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    main()
