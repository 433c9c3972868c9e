"""Closed forms the validation cases are checked against (Python 3 stdlib).

Every formula is derived in docs/validation.md; the section of that page is
named at each function. Nothing here reads engine output.
"""

import math

G = 9.81


def sphere_mass(radius, density):
    return density * 4.0 / 3.0 * math.pi * radius**3


def sphere_inertia(radius, density):
    return 0.4 * sphere_mass(radius, density) * radius**2


# --- linear spring-dashpot, normal impact (validation.md, "Normal impact") --

def zeta_for_restitution(e):
    """Damping ratio whose free (attraction allowed) half cycle gives e."""
    if e >= 1.0:
        return 0.0
    le = math.log(e)
    return -le / math.sqrt(math.pi**2 + le**2)


def restitution_attraction(zeta):
    return math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta**2))


def restitution_no_attraction(zeta):
    """Force ends at Fn = 0, phase pi - 2 asin(zeta), separation speed e^-zeta w0 t."""
    s = math.sqrt(1.0 - zeta**2)
    return math.exp(-zeta * (math.pi - 2.0 * math.asin(zeta)) / s)


def contact_time_attraction(kn, m_eff, zeta):
    w0 = math.sqrt(kn / m_eff)
    return math.pi / (w0 * math.sqrt(1.0 - zeta**2))


def contact_time_no_attraction(kn, m_eff, zeta):
    w0 = math.sqrt(kn / m_eff)
    return (math.pi - 2.0 * math.asin(zeta)) / (w0 * math.sqrt(1.0 - zeta**2))


def zeta_for_restitution_no_attraction(e):
    """Inverts restitution_no_attraction by bisection (it falls monotonically)."""
    if e >= 1.0:
        return 0.0
    lo, hi = 0.0, 1.0 - 1e-12
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if restitution_no_attraction(mid) > e:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def gamma_n(kn, m_eff, zeta):
    return 2.0 * zeta * math.sqrt(kn * m_eff)


# --- Hertz (validation.md, "Hertz comparison") -----------------------------

def hertz_effective_modulus(e1, nu1, e2, nu2):
    return 1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)


def hertz_impact(m_eff, r_eff, e_star, v):
    """Elastic Hertz impact: maximum overlap, maximum force, contact time."""
    delta = (15.0 * m_eff * v**2 / (16.0 * e_star * math.sqrt(r_eff))) ** 0.4
    force = 4.0 / 3.0 * e_star * math.sqrt(r_eff) * delta**1.5
    # t_c = 2 int_0^dmax dd / sqrt(v^2 - (8/15) E* sqrt(R) d^(5/2)/m) = c delta/v,
    # c = 2 int_0^1 du / sqrt(1 - u^(5/2)) (midpoint rule after u = 1 - s^2)
    c = hertz_time_factor()
    return delta, force, c * delta / v


def hertz_time_factor(n=20000):
    # u = 1 - s^2 removes the 1/sqrt singularity at u = 1:
    # int_0^1 du / sqrt(1 - u^a) = int_0^1 2 s ds / sqrt(1 - (1 - s^2)^a)
    total = 0.0
    for k in range(n):
        s = (k + 0.5) / n
        total += 2.0 * s / math.sqrt(1.0 - (1.0 - s * s) ** 2.5) / n
    return 2.0 * total


def linear_stiffness_matching_hertz(m_eff, r_eff, e_star, v):
    """kn whose linear spring reaches Hertz's maximum overlap at speed v."""
    delta, _, _ = hertz_impact(m_eff, r_eff, e_star, v)
    return m_eff * v**2 / delta**2


# --- oblique impact in gross sliding (validation.md, "Oblique impact") -----

def oblique_gross_sliding(theta, v, radius, mu, e):
    """Sphere on a wall, incidence theta from the normal, Coulomb sliding
    throughout: tangential restitution, rebound spin, contact-point rebound
    angle (radians)."""
    t = math.tan(theta)
    jt = mu * (1.0 + e)  # tangential impulse / (m v_n)
    et = 1.0 - jt / t
    spin = 2.5 * jt * v * math.cos(theta) / radius
    rebound = math.atan((t - 3.5 * jt) / e)
    return et, spin, rebound


def oblique_sliding_threshold(mu, e):
    """tan(theta) above which the contact point slides for the whole contact."""
    return 3.5 * mu * (1.0 + e)


def spinning_pair_gross_sliding(w0, v0, radius, mu, e):
    """Two equal spheres, approach speeds +-v0, both spinning w0 about the
    same axis (their surfaces meet moving in opposite directions): sideways
    speed of each and common final spin, Coulomb sliding throughout."""
    jt = mu * (1.0 + e) * v0  # tangential impulse / m
    return jt, w0 - 2.5 * jt / radius


def spinning_pair_threshold(v0, radius, mu, e):
    return 3.5 * mu * (1.0 + e) * v0 / radius


# --- no-slip linear tangential spring (validation.md, "Tangential spring") -

def tangential_ratio_no_slip(kt_over_kn):
    """Contact-point tangential velocity after / before, undamped, no slip."""
    return math.cos(math.pi * math.sqrt(3.5 * kt_over_kn))


# --- rolling resistance (validation.md, "Rolling resistance") --------------

def rolling_deceleration(mu_r, slope=0.0):
    """Rolling without slip under the capped rolling torque mu_r Fn R
    (wall: R* = R), on a plane inclined by `slope` (rad), down-slope positive."""
    return 5.0 / 7.0 * G * (math.sin(slope) - mu_r * math.cos(slope))


def spin_down_rate(mu_r, mass, r_star, inertia, normal_force=None):
    fn = mass * G if normal_force is None else normal_force
    return mu_r * fn * r_star / inertia


def spin_with_viscous(t, w0, cap_torque, eta, inertia):
    """I w' = -M - eta w: w(t) (until it stops)."""
    if eta == 0.0:
        return w0 - cap_torque / inertia * t
    tau = inertia / eta
    if cap_torque == 0.0:
        return w0 * math.exp(-t / tau)
    return (w0 + cap_torque / eta) * math.exp(-t / tau) - cap_torque / eta


def stop_time_with_viscous(w0, cap_torque, eta, inertia):
    if eta == 0.0:
        return w0 * inertia / cap_torque
    return inertia / eta * math.log(1.0 + eta * w0 / cap_torque)


# --- bonded beams and chains (validation.md, "Bonds") ----------------------

def chain_axial_frequency(p, n, k_axial, mass):
    """Free-free chain of n masses and n-1 springs, mode p (1..n-1)."""
    return 2.0 * math.sqrt(k_axial / mass) * math.sin(p * math.pi / (2.0 * n))


def chain_axial_mode_shape(p, n, j):
    """Sphere j (1..n) of mode p of the free-free chain."""
    return math.cos(p * math.pi * (j - 0.5) / n)


def cantilever_tip_discrete(n_bonds, a, load, k_bend, k_shear):
    """Tip deflection of n_bonds rigid links with a rotational spring k_bend
    (moment per angle) and a shear spring k_shear at each bond's midpoint."""
    s = sum(((n_bonds - k) - 0.5) ** 2 for k in range(n_bonds)) * a * a
    return load * s / k_bend + n_bonds * load / k_shear


def cantilever_tip_continuum(length, load, ei, kga):
    return load * length**3 / (3.0 * ei) + load * length / kga


def cantilever_flexibility(n_free, a, k_bend, k_shear):
    """Deflection of sphere i under a unit load on sphere j (i, j = 1..n_free;
    sphere 0 clamped), springs at the bond midpoints (k - 1/2) a."""
    g = [[0.0] * n_free for _ in range(n_free)]
    for i in range(n_free):
        for j in range(n_free):
            xi, xj = (i + 1) * a, (j + 1) * a
            total = 0.0
            for k in range(1, min(i, j) + 2):
                mk = (k - 0.5) * a
                total += (xi - mk) * (xj - mk) / k_bend + 1.0 / k_shear
            g[i][j] = total
    return g


def cantilever_first_frequency_discrete(n_free, a, mass, k_bend, k_shear):
    """Lowest angular frequency of the lumped chain (rotary inertia of the
    spheres neglected): 1/sqrt(mass lambda_max(G)), power iteration."""
    g = cantilever_flexibility(n_free, a, k_bend, k_shear)
    x = [float(i + 1) ** 2 for i in range(n_free)]
    lam = 0.0
    for _ in range(500):
        y = [sum(g[i][j] * x[j] for j in range(n_free)) for i in range(n_free)]
        norm = math.sqrt(sum(v * v for v in y))
        lam_new = norm / math.sqrt(sum(v * v for v in x))
        x = [v / norm for v in y]
        if abs(lam_new - lam) <= 1e-15 * lam_new:
            break
        lam = lam_new
    return 1.0 / math.sqrt(mass * lam_new), x


def cantilever_first_frequency_continuum(length, ei, mass_per_length):
    beta = 1.8751040687119611  # first root of cos(b) cosh(b) = -1
    return beta**2 * math.sqrt(ei / (mass_per_length * length**4))


def cantilever_static_shape(x, length):
    """Euler-Bernoulli deflection shape under a tip load (up to a factor)."""
    return x * x * (3.0 * length - x)
