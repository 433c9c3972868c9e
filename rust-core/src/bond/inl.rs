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

pub(super) type V = [f64; 3];

/// No normal force within this compression or stretch of zero (m).
pub(super) const DEAD_ZONE: f64 = 1e-15;

#[inline(always)]
pub(super) fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline(always)]
pub(super) fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
#[inline(always)]
pub(super) fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}
#[inline(always)]
pub(super) fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline(always)]
pub(super) fn norm(a: V) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}
#[inline(always)]
pub(super) fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
/// The part of `v` along `on`, with `on` normalised again first (INL's
/// projection does, and the last bits follow from it).
#[inline(always)]
pub(super) fn project(v: V, on: V) -> V {
    let len = norm(on);
    let inv = if len == 0.0 { 0.0 } else { 1.0 / len };
    let unit = scale(on, inv);
    scale(unit, dot(v, unit))
}
#[inline(always)]
pub(super) fn sgn(v: f64) -> f64 {
    ((0.0 < v) as i32 - (v < 0.0) as i32) as f64
}

/// The per-component multiplier of the force damping.
#[inline(always)]
pub(super) fn multiplier(rate: f64, force: f64, dt: f64, min_rate: f64, smooth: bool) -> f64 {
    if smooth {
        let floor = min_rate.max(0.01 * force * dt);
        (rate / floor).clamp(-1.0, 1.0)
    } else {
        sgn(rate)
    }
}

/// `F_k - eta |F_k| m_k` for each component.
#[inline(always)]
pub(super) fn damp_components(force: V, eta: f64, multipliers: V) -> V {
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
pub(super) struct Geometry {
    /// From `j` (or the wall point) to `i`.
    pub(super) delta: V,
    pub(super) r: f64,
    /// The bond radius's base: `min(R_i, R_j)`, or `R_i` at a wall.
    pub(super) radius: f64,
    pub(super) lever_i: f64,
    pub(super) lever_j: f64,
    /// The spin that turns the bond's contact point with the spheres.
    pub(super) contact_spin: V,
}

pub(super) fn pair_geometry(kin: &PairKinematics) -> Geometry {
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
pub(super) fn wall_geometry(kin: &PairKinematics) -> Geometry {
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

pub(super) fn nothing(
    state: &mut BondState,
    out: &mut BondOutput,
    status: BondStatus,
    mode: BreakMode,
    delta: f64,
) {
    *out = BondOutput {
        delta,
        ..BondOutput::default()
    };
    if status == BondStatus::Broken {
        state.mark_broken();
    }
    out.status = status as i32;
    out.break_mode = mode as i32;
}

/// What INL's two bond laws (this one and its linear bond, `super::linear`)
/// compute alike before their loads: the geometry, the section, and the
/// relative motion split along and across the axis.
pub(super) struct Frame {
    pub(super) g: Geometry,
    /// `r0 - r`.
    pub(super) d: f64,
    /// The unit vector from `j` to `i`.
    pub(super) en: V,
    pub(super) rb: f64,
    pub(super) area: f64,
    pub(super) polar: f64,
    pub(super) inertia: f64,
    /// INL's minimum velocity of smooth damping.
    pub(super) min_rate: f64,
    pub(super) vn: V,
    /// The slip of the contact point.
    pub(super) slip: V,
    pub(super) wn: V,
    pub(super) wt: V,
}

/// The [`Frame`] of an intact bond, or `None` when the bond is not intact
/// or breaks by distance in this step (`commit`): then it exerts nothing,
/// and `state` and `out` say so.
pub(super) fn frame(
    laws: &BondLaws,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
    wall: bool,
    commit: bool,
) -> Result<Option<Frame>, KinematicsError> {
    let status = state.status();
    if status != BondStatus::Intact {
        nothing(state, out, status, BreakMode::None, 0.0);
        return Ok(None);
    }
    kin.check()?;
    let p = &laws.params;
    let g = if wall {
        wall_geometry(kin)
    } else {
        pair_geometry(kin)
    };
    if !(g.r > f64::MIN_POSITIVE) {
        return Err(KinematicsError::CoincidentCentres);
    }
    let d = state.rest - g.r;
    if commit && !laws.stress_break && g.r > p.max_distance {
        nothing(state, out, BondStatus::Broken, BreakMode::Distance, d);
        return Ok(None);
    }
    let en = scale(g.delta, 1.0 / g.r);
    let rb = p.lambda * g.radius;
    let area = PI * rb * rb;
    let polar = 0.5 * area * rb * rb;
    let vr = sub(kin.v_i, kin.v_j);
    let vn = project(vr, en);
    let slip = add(sub(vr, vn), cross(g.delta, g.contact_spin));
    let wr = sub(kin.w_i, kin.w_j);
    let wn = project(wr, en);
    Ok(Some(Frame {
        d,
        en,
        rb,
        area,
        polar,
        inertia: 0.5 * polar,
        min_rate: 1e-5 * g.radius / dt,
        vn,
        slip,
        wn,
        wt: sub(wr, wn),
        g,
    }))
}

/// A force damped as INL damps its bond forces, per Cartesian component
/// against the sign of its rate (smoothed with `smooth`); as it is without
/// `damping`.
#[inline(always)]
pub(super) fn damped_force(
    force: V,
    rate: V,
    eta: f64,
    f: &Frame,
    dt: f64,
    damping: bool,
    smooth: bool,
) -> V {
    if damping {
        let m = [0, 1, 2].map(|c| multiplier(rate[c], force[c], dt, f.min_rate, smooth));
        damp_components(force, eta, m)
    } else {
        force
    }
}

/// The normal force on `i` (undamped, damped) and its magnitude (positive
/// repels): `magnitude()` along the axis while a side of the law that is
/// on holds (`|d|` above [`DEAD_ZONE`]), nothing otherwise.
#[inline(always)]
pub(super) fn normal_force(
    laws: &BondLaws,
    f: &Frame,
    dt: f64,
    magnitude: impl FnOnce() -> f64,
) -> (V, V, f64) {
    let p = &laws.params;
    let on = BondParams::switch;
    if (on(p.tension) && f.d < -DEAD_ZONE) || (on(p.compression) && f.d > DEAD_ZONE) {
        let m = magnitude();
        let normal = scale(f.en, m);
        let damped = damped_force(
            normal,
            f.vn,
            p.eta_fn,
            f,
            dt,
            p.damping_on(),
            on(p.damping_smooth),
        );
        (normal, damped, m)
    } else {
        ([0.0; 3], [0.0; 3], 0.0)
    }
}

/// A torque damped as INL damps its bond torques, per Cartesian component
/// against the sign of its rate; as it is without `damping`.
#[inline(always)]
pub(super) fn damped_torque(torque: V, rate: V, eta: f64, damping: bool) -> V {
    if damping {
        damp_components(torque, eta, rate.map(sgn))
    } else {
        torque
    }
}

/// How a bond at compression `d` breaks with section stresses `sigma`,
/// `tau` against the strengths `max_sigma`, `max_tau`: strictly above,
/// the normal stress first.
#[inline(always)]
pub(super) fn stress_mode(sigma: f64, max_sigma: f64, tau: f64, max_tau: f64, d: f64) -> BreakMode {
    if max_sigma < sigma {
        if d < 0.0 {
            BreakMode::Tension
        } else {
            BreakMode::Compression
        }
    } else if max_tau < tau {
        BreakMode::Shear
    } else {
        BreakMode::None
    }
}

/// A bond broken by stress in this step: it exerts nothing; the output
/// keeps its normal force and stresses.
pub(super) fn broken(state: &mut BondState, out: &mut BondOutput, mode: BreakMode, f: &Frame, normal: f64) {
    let (sigma, tau) = (out.sigma, out.tau);
    nothing(state, out, BondStatus::Broken, mode, f.d);
    (out.normal_force, out.sigma, out.tau) = (normal, sigma, tau);
}

/// The loads of an intact bond on both spheres from its damped normal and
/// shear forces and twisting and bending torques.
pub(super) fn write_loads(out: &mut BondOutput, f: &Frame, normal: V, shear: V, twist: V, bend: V) {
    let arm = cross(shear, f.en);
    out.force_i = add(normal, shear);
    out.torque_i = [0, 1, 2].map(|c| f.g.lever_i * arm[c] + twist[c] + bend[c]);
    out.torque_j = [0, 1, 2].map(|c| f.g.lever_j * arm[c] - twist[c] - bend[c]);
    out.status = BondStatus::Intact as i32;
    out.break_mode = BreakMode::None as i32;
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
    let Some(f) = frame(laws, kin, dt, state, out, wall, commit)? else {
        return Ok(());
    };
    let (d, en, area) = (f.d, f.en, f.area);
    let p = &laws.params;
    let on = BondParams::switch;
    let damping = p.damping_on();
    let smooth = on(p.damping_smooth);

    // Extremes of d: the law reads them before the other side's is zeroed.
    let max = if d > state.delta_max { d } else { state.delta_max };
    let min = if d < state.delta_min { d } else { state.delta_min };
    state.delta_max = if d < 0.0 { 0.0 } else { max };
    state.delta_min = if d > 0.0 { 0.0 } else { min };

    let (normal, normal_damped, magnitude) =
        normal_force(laws, &f, dt, || normal_magnitude(laws, d, max, min, area));

    let mut shear = state.shear_force;
    let mut shear_damped = [0.0; 3];
    if on(p.shear) {
        let increment = scale(f.slip, -p.k_ft * area * dt);
        shear = add(sub(shear, project(shear, en)), increment);
        shear_damped = damped_force(shear, f.slip, p.eta_ft, &f, dt, damping, smooth);
    }

    let twist_extremes = [state.twist_max, state.twist_min, state.bend_opposite];
    let mut twist_angle = state.twist_angle;
    let (mut twist, mut twist_damped) = ([0.0; 3], [0.0; 3]);
    if on(p.twist) {
        twist_angle = add(twist_angle, scale(f.wn, dt));
        let next;
        (twist, next) = torque_law(twist_angle, twist_extremes, p.k_tn, p.ku_tn, p.kc_tn, f.polar);
        [state.twist_max, state.twist_min, state.bend_opposite] = next;
        twist_damped = damped_torque(twist, f.wn, p.eta_tn, damping);
    }
    let mut bend_angle = state.bend_angle;
    let (mut bend, mut bend_damped) = ([0.0; 3], [0.0; 3]);
    if on(p.bend) {
        bend_angle = add(bend_angle, scale(f.wt, dt));
        let next;
        (bend, next) = torque_law(
            bend_angle,
            state.bend_history,
            p.k_tt,
            p.ku_tt,
            p.kc_tt,
            f.inertia,
        );
        state.bend_history = next;
        bend_damped = damped_torque(bend, f.wt, p.eta_tt, damping);
    }

    out.delta = d;
    out.normal_force = magnitude;
    out.sigma = norm(normal) / area + norm(bend) * f.rb / f.inertia;
    out.tau = norm(shear) / area + norm(twist) * f.rb / f.polar;
    if commit && laws.stress_break {
        let tension = on(p.use_ratio) && d < -DEAD_ZONE;
        let max_sigma = p.max_sigma * if tension { p.tension_compression_ratio } else { 1.0 };
        let mode = stress_mode(out.sigma, max_sigma, out.tau, p.max_tau, d);
        if mode != BreakMode::None {
            broken(state, out, mode, &f, magnitude);
            return Ok(());
        }
    }

    write_loads(out, &f, normal_damped, shear_damped, twist_damped, bend_damped);
    if commit {
        state.shear_force = shear;
        state.twist_angle = twist_angle;
        state.bend_angle = bend_angle;
    }
    Ok(())
}
