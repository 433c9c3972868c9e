//! LIGGGHTS-INL's `cohesion bond/nonlinear` as its code computes it
//! (`inl_compatible`, LIGGGHTS `inlCompatible on`; docs/models/bond-nonlinear.md,
//! "LIGGGHTS-INL's code"). It differs from the default law in:
//!
//! - compression: `k_fn1 sqrt(d)`, `ku_fn1 sqrt(d) + (k_fn1 - ku_fn1)
//!   sqrt(dmax)` and `-kc_fn1 sqrt(d)`, without the section `A` (tension
//!   keeps it), and no normal force within 1e-15 m of `d = 0`;
//! - history: the extremes of the other side are zeroed on every sign change;
//! - twisting and bending: the signed loop on each Cartesian component of
//!   the accumulated angles, which are not projected back on the axis or
//!   the tangent plane; the torques are damped per component by `sgn`;
//! - damping of the forces: per Cartesian component, `F_k - eta |F_k|
//!   m_k`, with `m_k = sgn(v_k)`, or with smooth damping
//!   `clamp(v_k / max(v_min, 0.01 F_k dt), -1, 1)` and `v_min = 1e-5
//!   min(R_i, R_j) / dt`;
//! - stress breakage: strictly above the strength, the stresses from the
//!   lengths of the undamped load vectors;
//! - walls: the bond runs from the centre to the contact point of its
//!   creation, carried with the wall (not to a mirror sphere): `r` is the
//!   distance to it, so is the shear's lever arm, and half the particle's
//!   spin enters the slip;
//! - a run's setup pass: a trial step (`commit` off), whose loads are the
//!   next step's; only the history extremes move.
//!
//! The arithmetic follows INL's order of operations, and `powf` where INL
//! calls `pow`, so that both give the same bits (`tests/validation/inl/`).
//!
//! The state is the 19 slots of [`BondState`]: the per-component extremes
//! fit because the reset rule leaves at most one side of a component
//! non-zero, so each is kept as one signed number (twisting in
//! `twist_max`, `twist_min`, `bend_opposite`; bending in `bend_history`).
//!
//! Scalar only: [`super::model::BondModel`] steps this law one bond at a
//! time on every path (the scalar steps of `super::dispatch`, reading the
//! switches as `super::switches::Inl`;
//! `inl_compatible_runs_scalar_on_every_path_with_the_bits_of_a_single_step`).

use super::breakage::BreakMode;
use super::laws::BondLaws;
use super::params::BondParams;
use super::state::{BondOutput, BondState, BondStatus};
use crate::kinematics::{KinematicsError, PairKinematics};
use std::f64::consts::PI;

type V = [f64; 3];

/// No normal force within this compression or stretch of zero (m).
const DEAD_ZONE: f64 = 1e-15;

#[inline(always)]
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline(always)]
fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
#[inline(always)]
fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}
#[inline(always)]
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline(always)]
fn norm(a: V) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}
#[inline(always)]
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
/// The part of `v` along `on`, with `on` normalised again first (INL's
/// projection does, and the last bits follow from it).
#[inline(always)]
fn project(v: V, on: V) -> V {
    let len = norm(on);
    let inv = if len == 0.0 { 0.0 } else { 1.0 / len };
    let unit = scale(on, inv);
    scale(unit, dot(v, unit))
}
#[inline(always)]
fn sgn(v: f64) -> f64 {
    ((0.0 < v) as i32 - (v < 0.0) as i32) as f64
}

/// The per-component multiplier of the force damping.
#[inline(always)]
fn multiplier(rate: f64, force: f64, dt: f64, min_rate: f64, smooth: bool) -> f64 {
    if smooth {
        let floor = min_rate.max(0.01 * force * dt);
        (rate / floor).clamp(-1.0, 1.0)
    } else {
        sgn(rate)
    }
}

/// `F_k - eta |F_k| m_k` for each component.
#[inline(always)]
fn damp_components(force: V, eta: f64, multipliers: V) -> V {
    [
        force[0] - eta * force[0].abs() * multipliers[0],
        force[1] - eta * force[1].abs() * multipliers[1],
        force[2] - eta * force[2].abs() * multipliers[2],
    ]
}

/// One component of the twisting or bending law: the torque on `i` and the
/// component's new signed extreme. `extreme` is the side's extreme (> 0:
/// the positive side's maximum, < 0: the negative side's minimum).
#[inline(always)]
fn torque_component(theta: f64, extreme: f64, k: f64, ku: f64, kc: f64, moment: f64) -> (f64, f64) {
    let (mut max, mut min) = if extreme > 0.0 {
        (extreme, 0.0)
    } else {
        (0.0, extreme)
    };
    if theta > 0.0 {
        min = 0.0;
    } else if theta < 0.0 {
        max = 0.0;
    }
    let ratio = (ku - k) / (ku + kc);
    let (c1, c2) = (ratio * max, ratio * min);
    let torque = if theta >= max || theta <= min {
        -k * moment * theta
    } else if theta > c1 {
        -ku * moment * theta + (ku - k) * moment * max
    } else if theta >= c2 {
        kc * moment * theta
    } else {
        -ku * moment * theta + (ku - k) * moment * min
    };
    if theta > max {
        max = theta;
    }
    if theta < min {
        min = theta;
    }
    (torque, if max != 0.0 { max } else { min })
}

/// The torque vector of a twisting or bending law on each component, and
/// the extremes after the step.
#[inline(always)]
fn torque_law(theta: V, extremes: V, k: f64, ku: f64, kc: f64, moment: f64) -> (V, V) {
    let mut torque = [0.0; 3];
    let mut next = [0.0; 3];
    for c in 0..3 {
        (torque[c], next[c]) = torque_component(theta[c], extremes[c], k, ku, kc, moment);
    }
    (torque, next)
}

/// The normal force's magnitude (positive repels) at compression `d` with
/// the extremes `max`, `min` of this step.
#[inline(always)]
fn normal_magnitude(laws: &BondLaws, d: f64, max: f64, min: f64, area: f64) -> f64 {
    let p = &laws.params;
    let c1 = ((p.ku_fn1 - p.k_fn1) / (p.ku_fn1 + p.kc_fn1)).powf(2.0) * max;
    let c2 = ((p.ku_fn2 - p.k_fn2) / (p.ku_fn2 + p.kc_fn2)).powf(1.0) * min;
    if d < min {
        p.k_fn2 * area * d
    } else if d < c2 {
        p.ku_fn2 * area * d + (p.k_fn2 - p.ku_fn2) * area * min
    } else if d < 0.0 {
        -p.kc_fn2 * area * d
    } else if d < c1 {
        -p.kc_fn1 * d.abs().powf(0.5)
    } else if d < max {
        p.ku_fn1 * d.abs().powf(0.5) + (p.k_fn1 - p.ku_fn1) * max.abs().powf(0.5)
    } else {
        p.k_fn1 * d.abs().powf(0.5)
    }
}

/// A bond's geometry as INL sees it: between two spheres, or between a
/// sphere and the contact point on a wall.
struct Geometry {
    /// From `j` (or the wall point) to `i`.
    delta: V,
    r: f64,
    /// The bond radius's base: `min(R_i, R_j)`, or `R_i` at a wall.
    radius: f64,
    lever_i: f64,
    lever_j: f64,
    /// The spin that turns the bond's contact point with the spheres.
    contact_spin: V,
}

fn pair_geometry(kin: &PairKinematics) -> Geometry {
    let delta = sub(kin.x_i, kin.x_j);
    let r = dot(delta, delta).sqrt();
    let (ri, rj) = (kin.radius_i, kin.radius_j);
    let inv_sum = 1.0 / (ri + rj);
    Geometry {
        delta,
        r,
        radius: ri.min(rj),
        lever_i: r * ri * inv_sum,
        lever_j: r * rj * inv_sum,
        contact_spin: add(scale(kin.w_i, ri * inv_sum), scale(kin.w_j, rj * inv_sum)),
    }
}

/// A wall bond: `x_j` is the contact point of the bond's creation, carried
/// with the wall (`super::wall`).
fn wall_geometry(kin: &PairKinematics) -> Geometry {
    let delta = sub(kin.x_i, kin.x_j);
    let r = norm(delta);
    Geometry {
        delta,
        r,
        radius: kin.radius_i,
        lever_i: r,
        lever_j: r,
        contact_spin: scale(kin.w_i, 0.5),
    }
}

fn nothing(state: &mut BondState, out: &mut BondOutput, status: BondStatus, mode: BreakMode, delta: f64) {
    *out = BondOutput {
        delta,
        ..BondOutput::default()
    };
    state.status = status as i32 as f64;
    out.status = status as i32;
    out.break_mode = mode as i32;
}

/// Advances one bond by `dt` with INL's law and writes the loads on both
/// spheres; `wall`: `j` is the contact point of a wall bond. A bond that is
/// not intact, or breaks in this step, exerts nothing.
///
/// Without `commit` (a run's setup pass) it is INL's trial step: the loads
/// of a step ahead, no break, and of the state only the extremes move
/// (INL writes them whatever the pass).
pub(crate) fn inl_step(
    laws: &BondLaws,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
    wall: bool,
    commit: bool,
) -> Result<(), KinematicsError> {
    let status = state.status();
    if status != BondStatus::Intact {
        nothing(state, out, status, BreakMode::None, 0.0);
        return Ok(());
    }
    kin.check()?;
    let p = &laws.params;
    let on = BondParams::switch;
    let g = if wall {
        wall_geometry(kin)
    } else {
        pair_geometry(kin)
    };
    if !(g.r > f64::MIN_POSITIVE) {
        return Err(KinematicsError::CoincidentCentres);
    }
    let d = state.r0 - g.r;
    if commit && !laws.stress_break && g.r > p.max_distance {
        nothing(state, out, BondStatus::Broken, BreakMode::Distance, d);
        return Ok(());
    }
    let en = scale(g.delta, 1.0 / g.r);
    let rb = p.lambda * g.radius;
    let area = PI * rb * rb;
    let polar = 0.5 * area * rb * rb;
    let inertia = 0.5 * polar;
    let damping = p.damping_on();
    let smooth = on(p.damping_smooth);
    let min_rate = 1e-5 * g.radius / dt;

    let vr = sub(kin.v_i, kin.v_j);
    let vn = project(vr, en);
    let vt = sub(vr, vn);
    let slip = add(vt, cross(g.delta, g.contact_spin));
    let wr = sub(kin.w_i, kin.w_j);
    let wn = project(wr, en);
    let wt = sub(wr, wn);

    // Extremes of d: the law reads them before the other side's is zeroed.
    let max = if d > state.delta_max { d } else { state.delta_max };
    let min = if d < state.delta_min { d } else { state.delta_min };
    state.delta_max = if d < 0.0 { 0.0 } else { max };
    state.delta_min = if d > 0.0 { 0.0 } else { min };

    let (mut normal, mut normal_damped, mut magnitude) = ([0.0; 3], [0.0; 3], 0.0);
    if (on(p.tension) && d < -DEAD_ZONE) || (on(p.compression) && d > DEAD_ZONE) {
        magnitude = normal_magnitude(laws, d, max, min, area);
        normal = scale(en, magnitude);
        normal_damped = if damping {
            let m = [0, 1, 2].map(|c| multiplier(vn[c], normal[c], dt, min_rate, smooth));
            damp_components(normal, p.eta_fn, m)
        } else {
            normal
        };
    }

    let mut shear = state.shear_force;
    let mut shear_damped = [0.0; 3];
    if on(p.shear) {
        let increment = scale(slip, -p.k_ft * area * dt);
        shear = add(sub(shear, project(shear, en)), increment);
        shear_damped = if damping {
            let m = [0, 1, 2].map(|c| multiplier(slip[c], shear[c], dt, min_rate, smooth));
            damp_components(shear, p.eta_ft, m)
        } else {
            shear
        };
    }

    let twist_extremes = [state.twist_max, state.twist_min, state.bend_opposite];
    let mut twist_angle = state.twist_angle;
    let (mut twist, mut twist_damped) = ([0.0; 3], [0.0; 3]);
    if on(p.twist) {
        twist_angle = add(twist_angle, scale(wn, dt));
        let next;
        (twist, next) = torque_law(twist_angle, twist_extremes, p.k_tn, p.ku_tn, p.kc_tn, polar);
        [state.twist_max, state.twist_min, state.bend_opposite] = next;
        twist_damped = if damping {
            damp_components(twist, p.eta_tn, wn.map(sgn))
        } else {
            twist
        };
    }
    let mut bend_angle = state.bend_angle;
    let (mut bend, mut bend_damped) = ([0.0; 3], [0.0; 3]);
    if on(p.bend) {
        bend_angle = add(bend_angle, scale(wt, dt));
        let next;
        (bend, next) = torque_law(bend_angle, state.bend_history, p.k_tt, p.ku_tt, p.kc_tt, inertia);
        state.bend_history = next;
        bend_damped = if damping {
            damp_components(bend, p.eta_tt, wt.map(sgn))
        } else {
            bend
        };
    }

    let sigma = norm(normal) / area + norm(bend) * rb / inertia;
    let tau = norm(shear) / area + norm(twist) * rb / polar;
    out.delta = d;
    out.normal_force = magnitude;
    out.sigma = sigma;
    out.tau = tau;
    if commit && laws.stress_break {
        let tension = on(p.use_ratio) && d < -DEAD_ZONE;
        let max_sigma = p.max_sigma * if tension { p.tension_compression_ratio } else { 1.0 };
        let mode = if max_sigma < sigma {
            if d < 0.0 {
                BreakMode::Tension
            } else {
                BreakMode::Compression
            }
        } else if p.max_tau < tau {
            BreakMode::Shear
        } else {
            BreakMode::None
        };
        if mode != BreakMode::None {
            let (s, t) = (out.sigma, out.tau);
            nothing(state, out, BondStatus::Broken, mode, d);
            (out.normal_force, out.sigma, out.tau) = (magnitude, s, t);
            return Ok(());
        }
    }

    let arm = cross(shear_damped, en);
    let force = add(normal_damped, shear_damped);
    out.force_i = force;
    out.torque_i = [0, 1, 2].map(|c| g.lever_i * arm[c] + twist_damped[c] + bend_damped[c]);
    out.torque_j = [0, 1, 2].map(|c| g.lever_j * arm[c] - twist_damped[c] - bend_damped[c]);
    if commit {
        state.shear_force = shear;
        state.twist_angle = twist_angle;
        state.bend_angle = bend_angle;
    }
    out.status = BondStatus::Intact as i32;
    out.break_mode = BreakMode::None as i32;
    Ok(())
}
