//! One bond step, generic over the active degrees of freedom: each switched
//! off part is removed at compile time, so it costs nothing. One
//! monomorphised kernel per combination of the seven feature bits.

use super::breakage::{distance_criterion, section_stresses, stress_criterion, BreakMode};
use super::damping::{damp_along, damp_scalar, scaled_unit, scaled_units, unit_scale};
use super::lanes::norms;
use super::model::BondModel;
use super::section::{lever_arms, section};
use super::shear::update_shear_force;
use super::state::{BondOutput, BondState, BondStatus};
use super::twist_bend::{
    advance_bend, advance_twist, restoring_torque, restoring_torques, split_relative_spin,
};
use crate::kinematics::{centre_line, tangential_slip_velocity, KinematicsError, PairKinematics};
use crate::vector::{v3, Vec3};
use seq_macro::seq;

pub const TENSION: u32 = 1;
pub const COMPRESSION: u32 = 2;
pub const SHEAR: u32 = 4;
pub const TWIST: u32 = 8;
pub const BEND: u32 = 16;
pub const DAMPING: u32 = 32;
pub const SMOOTH: u32 = 64;
pub const FEATURE_COMBINATIONS: usize = 128;

pub type Kernel =
    fn(&BondModel, &PairKinematics, f64, &mut BondState, &mut BondOutput) -> Result<(), KinematicsError>;
pub type BatchKernel = fn(
    &BondModel,
    &[PairKinematics],
    f64,
    &mut [BondState],
    &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)>;

#[inline(always)]
fn finish(state: &mut BondState, out: &mut BondOutput, status: BondStatus, mode: BreakMode) {
    state.status = status as i32 as f64;
    out.force_i = [0.0; 3];
    out.torque_i = [0.0; 3];
    out.torque_j = [0.0; 3];
    out.status = status as i32;
    out.break_mode = mode as i32;
}

/// Advances one bond by `dt` and writes the loads on both spheres. A bond
/// that is not intact, or breaks in this step, exerts nothing.
#[inline(always)]
pub fn bond_step<const F: u32>(
    model: &BondModel,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    let status = state.status();
    if status != BondStatus::Intact {
        *out = BondOutput::default();
        finish(state, out, status, BreakMode::None);
        return Ok(());
    }
    kin.check()?;
    let line = centre_line(kin)?;
    let n = line.n;
    let delta = state.r0 - line.r;
    out.delta = delta;
    if !model.stress_break {
        let mode = distance_criterion(line.r, model.params.max_distance);
        if mode != BreakMode::None {
            out.sigma = 0.0;
            out.tau = 0.0;
            out.normal_force = 0.0;
            finish(state, out, BondStatus::Broken, mode);
            return Ok(());
        }
    }
    let sec = section(model.params.lambda, kin.radius_i, kin.radius_j);

    let mut normal_force = 0.0;
    if F & (TENSION | COMPRESSION) != 0 {
        let (hi, lo) = model
            .normal
            .update_history(delta, state.delta_max, state.delta_min);
        state.delta_max = hi;
        state.delta_min = lo;
        normal_force = sec.area
            * model
                .normal
                .stress(delta, hi, lo, F & TENSION != 0, F & COMPRESSION != 0);
    }

    let (mut lever_i, mut lever_j) = (0.0, 0.0);
    let mut slip = Vec3::zeros();
    let mut shear_force = Vec3::zeros();
    if F & SHEAR != 0 {
        (lever_i, lever_j) = lever_arms(line.r, kin.radius_i, kin.radius_j);
        slip = tangential_slip_velocity(kin, n, lever_i, lever_j);
        shear_force = update_shear_force(v3(state.shear_force), model.params.k_ft * sec.area, dt, slip, n);
        state.shear_force = shear_force.into();
    }

    let (twist, bend) = (F & TWIST != 0, F & BEND != 0);
    let (mut w_along, mut w_across) = (Vec3::zeros(), Vec3::zeros());
    let (mut twist_torque, mut bend_torque) = (Vec3::zeros(), Vec3::zeros());
    if twist || bend {
        (w_along, w_across) = split_relative_spin(v3(kin.w_i) - v3(kin.w_j), n);
        if twist && bend {
            let theta_t = advance_twist(v3(state.twist_angle), w_along, n, dt);
            let theta_b = advance_bend(v3(state.bend_angle), w_across, n, dt);
            let ((t, tm), (b, bm)) = restoring_torques(
                (theta_t, state.twist_max, &model.twist, sec.polar),
                (theta_b, state.bend_max, &model.bend, sec.inertia),
            );
            state.twist_angle = theta_t.into();
            state.twist_max = tm;
            twist_torque = t;
            state.bend_angle = theta_b.into();
            state.bend_max = bm;
            bend_torque = b;
        } else if twist {
            let theta = advance_twist(v3(state.twist_angle), w_along, n, dt);
            let (t, m) = restoring_torque(theta, state.twist_max, &model.twist, sec.polar);
            state.twist_angle = theta.into();
            state.twist_max = m;
            twist_torque = t;
        } else {
            let theta = advance_bend(v3(state.bend_angle), w_across, n, dt);
            let (t, m) = restoring_torque(theta, state.bend_max, &model.bend, sec.inertia);
            state.bend_angle = theta.into();
            state.bend_max = m;
            bend_torque = t;
        }
    }

    // Lengths, two per instruction: the loads (for the stresses and the
    // damping) and, with damping, the rates the damping opposes.
    let (shear, damping) = (F & SHEAR != 0, F & DAMPING != 0);
    let (shear_magnitude, slip_speed) = norms(shear_force, shear, slip, shear && damping);
    let (twist_magnitude, bend_magnitude) = norms(twist_torque, twist, bend_torque, bend);
    let (sigma, tau) = section_stresses(
        normal_force,
        shear_magnitude,
        twist_magnitude,
        bend_magnitude,
        sec.rb,
        sec.area,
        sec.polar,
        sec.inertia,
    );
    out.normal_force = normal_force;
    out.sigma = sigma;
    out.tau = tau;
    if model.stress_break {
        let mode = stress_criterion(sigma, tau, delta, &model.limits);
        if mode != BreakMode::None {
            finish(state, out, BondStatus::Broken, mode);
            return Ok(());
        }
    }

    if damping {
        let smooth = F & SMOOTH != 0;
        let p = &model.params;
        let (ve, we) = (p.smooth_velocity, p.smooth_angular_velocity);
        if F & (TENSION | COMPRESSION) != 0 {
            let vn = (v3(kin.v_i) - v3(kin.v_j)).dot(&n);
            normal_force = damp_scalar(normal_force, p.eta_fn, vn, ve, smooth);
        }
        if shear {
            let direction = scaled_unit(slip, unit_scale(slip_speed, ve, smooth));
            shear_force = damp_along(shear_force, shear_magnitude, p.eta_ft, direction);
        }
        if twist || bend {
            let (spin_along, spin_across) = norms(w_along, twist, w_across, bend);
            let (scale_t, scale_b) = (
                unit_scale(spin_along, we, smooth),
                unit_scale(spin_across, we, smooth),
            );
            let (dir_t, dir_b) = if twist && bend {
                scaled_units(w_along, scale_t, w_across, scale_b)
            } else if twist {
                (scaled_unit(w_along, scale_t), Vec3::zeros())
            } else {
                (Vec3::zeros(), scaled_unit(w_across, scale_b))
            };
            if twist {
                twist_torque = damp_along(twist_torque, twist_magnitude, p.eta_tn, dir_t);
            }
            if bend {
                bend_torque = damp_along(bend_torque, bend_magnitude, p.eta_tt, dir_b);
            }
        }
    }

    let force = n * normal_force + shear_force;
    let couple = bend_torque + twist_torque;
    let (mut torque_i, mut torque_j) = (couple, -couple);
    if shear {
        let arm = n.cross(&shear_force);
        torque_i -= arm * lever_i;
        torque_j -= arm * lever_j;
    }
    out.force_i = force.into();
    out.torque_i = torque_i.into();
    out.torque_j = torque_j.into();
    out.status = BondStatus::Intact as i32;
    out.break_mode = BreakMode::None as i32;
    Ok(())
}

fn single<const F: u32>(
    model: &BondModel,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    bond_step::<F>(model, kin, dt, state, out)
}

fn batch<const F: u32>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    for (idx, ((k, s), o)) in kin.iter().zip(states.iter_mut()).zip(outs.iter_mut()).enumerate() {
        bond_step::<F>(model, k, dt, s, o).map_err(|e| (idx, e))?;
    }
    Ok(())
}

seq!(N in 0..128 {
    const SINGLE: [Kernel; FEATURE_COMBINATIONS] = [#(single::<N>,)*];
    const BATCH: [BatchKernel; FEATURE_COMBINATIONS] = [#(batch::<N>,)*];
});

pub fn single_kernel(features: u32) -> Kernel {
    SINGLE[features as usize % FEATURE_COMBINATIONS]
}

pub fn batch_kernel(features: u32) -> BatchKernel {
    BATCH[features as usize % FEATURE_COMBINATIONS]
}

impl BondModel {
    /// Advances one bond (see [`bond_step`]).
    #[inline]
    pub fn step(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut BondState,
        out: &mut BondOutput,
    ) -> Result<(), KinematicsError> {
        (self.single)(self, kin, dt, state, out)
    }

    /// Advances every bond of equal-length slices; stops at the first bad
    /// input and reports its index.
    pub fn step_batch(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        (self.batch)(self, kin, dt, states, outs)
    }
}
