//! LIGGGHTS-INL's linear bond (`cohesion bond`; `linear`,
//! docs/models/bond-linear.md): a Potyondy-Cundall parallel bond whose
//! springs are linear and whose loads, but for the normal force, build up
//! incrementally.
//!
//! - normal force `k_n A d` along the axis, `d = r0 - r`, for `|d|` above
//!   1e-15 m (tension and compression each switched on or off);
//! - shear force: the previous one with its part along the axis taken out,
//!   plus `-k_t A dt` times the slip of the contact point;
//! - twisting torque: the previous one projected on the axis, plus `-k_t J
//!   dt` times the relative spin about it;
//! - bending torque: the previous one projected on the relative spin across
//!   the axis, plus `-k_n I dt` times that spin; while that spin is exactly
//!   zero it is kept but not applied;
//! - dissipation (`dissipation`): each step relaxes the rest length toward
//!   `r` and scales the shear force and the torques by `1 - min(dt/T, 1)`;
//! - damping per Cartesian component, as INL's bond/nonlinear
//!   (`super::inl`): `F_k - eta |F_k| sgn(v_k)` (smoothly for the forces
//!   with `damping_smooth`), so it neither keeps the axis of a load nor
//!   commutes with a rotation of the frame;
//! - breakage by distance (`r > max_distance`) or by the section stresses
//!   of the undamped loads, `sigma = |F_n|/A + |T_t| rb/I` against
//!   `max_sigma` (times the ratio while stretched), `tau = |F_t|/A + |T_n|
//!   rb/J` against `max_tau` (plus `sgn(d) |F_n|/A tan(friction_angle)`
//!   under `drucker_prager`), strictly above the strength.
//!
//! The state is that of [`BondState`]: the shear force in `shear_force`,
//! the twisting and bending torques as the angles `-T_n / (k_t J)` and `-T_t
//! / (k_n I)` in `twist_angle` and `bend_angle` (the same update, scaled);
//! the extremes stay zero. Walls and the setup pass follow `super::inl`.
//! Scalar only, on every path, as `super::inl`.

use super::breakage::BreakMode;
use super::inl::{
    add, broken, damped_force, damped_torque, frame, norm, normal_force, project, scale, sgn, stress_mode,
    sub, write_loads, V,
};
use super::laws::BondLaws;
use super::params::BondParams;
use super::state::{BondOutput, BondState};
use crate::kinematics::{KinematicsError, PairKinematics};
use std::f64::consts::PI;

/// The fraction of a load the dissipation takes in a step of `dt` with
/// relaxation time `time` (0 without dissipation): `min(dt / T, 1)`, as INL
/// computes it from the inverted time.
#[inline(always)]
fn relaxed(on: bool, dt: f64, time: f64) -> f64 {
    if on {
        (dt * (1.0 / time)).min(1.0)
    } else {
        0.0
    }
}

/// A torque's angle after a step: the previous one projected on `onto`
/// (the direction the torque turns with), relaxed by `relax`, advanced by
/// `rate dt`.
#[inline(always)]
fn turned(angle: V, onto: V, relax: f64, rate: V, dt: f64) -> V {
    add(scale(project(angle, onto), 1.0 - relax), scale(rate, dt))
}

/// Advances one linear bond by `dt` and writes the loads on both spheres;
/// `wall`: `j` is the contact point of a wall bond. A bond that is not
/// intact, or breaks in this step, exerts nothing. Without `commit` (a
/// run's setup pass) it is a trial step: the loads of a step ahead, no
/// break, the state unchanged.
pub(crate) fn linear_step(
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
    let dissipation = on(p.dissipation);

    let (normal, normal_damped, magnitude) = normal_force(laws, &f, dt, || p.k_n * area * d);

    let mut shear = state.shear_force;
    let mut shear_damped = [0.0; 3];
    if on(p.shear) {
        let increment = scale(f.slip, -p.k_t * area * dt);
        shear = sub(shear, project(shear, en));
        shear = scale(shear, 1.0 - relaxed(dissipation, dt, p.dissipation_ft));
        shear = add(shear, increment);
        shear_damped = damped_force(shear, f.slip, p.eta_ft, &f, dt, damping, smooth);
    }

    let twist_stiffness = -p.k_t * f.polar;
    let mut twist_angle = state.twist_angle;
    let (mut twist, mut twist_damped) = (scale(twist_angle, twist_stiffness), [0.0; 3]);
    if on(p.twist) {
        let relax = relaxed(dissipation, dt, p.dissipation_tn);
        twist_angle = turned(twist_angle, en, relax, f.wn, dt);
        twist = scale(twist_angle, twist_stiffness);
        twist_damped = damped_torque(twist, f.wn, p.eta_tn, damping);
    }

    let bend_stiffness = -p.k_n * f.inertia;
    let mut bend_angle = state.bend_angle;
    let (mut bend, mut bend_damped) = (scale(bend_angle, bend_stiffness), [0.0; 3]);
    // Only a relative spin across the axis gives the torque a direction to
    // turn to; without one INL keeps the torque and does not apply it.
    let wt = f.wt;
    if on(p.bend) && (wt[0] * wt[0] + wt[1] * wt[1] + wt[2] * wt[2]) > 0.0 {
        let relax = relaxed(dissipation, dt, p.dissipation_tt);
        bend_angle = turned(bend_angle, wt, relax, wt, dt);
        bend = scale(bend_angle, bend_stiffness);
        bend_damped = damped_torque(bend, wt, p.eta_tt, damping);
    }

    let normal_stress = norm(normal) / area;
    out.delta = d;
    out.normal_force = magnitude;
    out.sigma = normal_stress + norm(bend) * f.rb / f.inertia;
    out.tau = norm(shear) / area + norm(twist) * f.rb / f.polar;
    if commit && laws.stress_break {
        let tension = on(p.use_ratio) && d < 1e-16;
        let max_sigma = p.max_sigma * if tension { p.tension_compression_ratio } else { 1.0 };
        let max_tau = if on(p.drucker_prager) {
            p.max_tau + sgn(d) * normal_stress * (p.friction_angle * PI / 180.0).tan()
        } else {
            p.max_tau
        };
        let mode = stress_mode(out.sigma, max_sigma, out.tau, max_tau, d);
        if mode != BreakMode::None {
            broken(state, out, mode, &f, magnitude);
            return Ok(());
        }
    }

    write_loads(out, &f, normal_damped, shear_damped, twist_damped, bend_damped);
    if commit {
        if dissipation && (on(p.tension) || on(p.compression)) {
            state.rest -= d * relaxed(true, dt, p.dissipation_fn);
        }
        state.shear_force = shear;
        state.twist_angle = twist_angle;
        state.bend_angle = bend_angle;
    }
    Ok(())
}
