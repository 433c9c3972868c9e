//! One bond step, generic over the active degrees of freedom: each switched
//! off part is removed at compile time, so it costs nothing. One
//! monomorphised kernel per combination of the seven feature bits.

use super::breakage::{distance_criterion, section_stresses, stress_criterion, BreakMode};
use super::damping::{damp_along, damp_scalar, reciprocal_unit, sign, unit_scale};
use super::lanes::{norms, reciprocals};
use super::model::BondModel;
use super::section::{lever_arms_scaled, section};
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
pub type ScatteredKernel = fn(
    &BondModel,
    &[PairKinematics],
    f64,
    &mut [&mut BondState],
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
    // The only divisions by the radii: the stresses and lever arms multiply.
    let (inv_rb, inv_radius_sum) = super::section::reciprocals(&sec, kin.radius_i, kin.radius_j);

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
        (lever_i, lever_j) = lever_arms_scaled(line.r, inv_radius_sum, kin.radius_i, kin.radius_j);
        slip = tangential_slip_velocity(kin, n, lever_i, lever_j);
        shear_force = update_shear_force(v3(state.shear_force), model.params.k_ft * sec.area, dt, slip, n);
        state.shear_force = shear_force.into();
    }

    let (twist, bend) = (F & TWIST != 0, F & BEND != 0);
    let (w_along, w_across, spin_rate) = if twist || bend {
        split_relative_spin(v3(kin.w_i) - v3(kin.w_j), n)
    } else {
        (Vec3::zeros(), Vec3::zeros(), 0.0)
    };
    let (mut twist_torque, mut bend_torque) = (Vec3::zeros(), Vec3::zeros());
    // |torque| = |h| * moment, from the laws (no square roots).
    let (mut twist_magnitude, mut bend_magnitude) = (0.0, 0.0);
    if twist || bend {
        if twist && bend {
            let theta_t = advance_twist(v3(state.twist_angle), w_along, n, dt);
            let theta_b = advance_bend(v3(state.bend_angle), w_across, n, dt);
            let ((t, tm, ta), (b, bm, ba)) = restoring_torques(
                (theta_t, state.twist_max, &model.twist, sec.polar),
                (theta_b, state.bend_max, &model.bend, sec.inertia),
            );
            state.twist_angle = theta_t.into();
            state.twist_max = tm;
            (twist_torque, twist_magnitude) = (t, ta);
            state.bend_angle = theta_b.into();
            state.bend_max = bm;
            (bend_torque, bend_magnitude) = (b, ba);
        } else if twist {
            let theta = advance_twist(v3(state.twist_angle), w_along, n, dt);
            let (t, m, a) = restoring_torque(theta, state.twist_max, &model.twist, sec.polar);
            state.twist_angle = theta.into();
            state.twist_max = m;
            (twist_torque, twist_magnitude) = (t, a);
        } else {
            let theta = advance_bend(v3(state.bend_angle), w_across, n, dt);
            let (t, m, a) = restoring_torque(theta, state.bend_max, &model.bend, sec.inertia);
            state.bend_angle = theta.into();
            state.bend_max = m;
            (bend_torque, bend_magnitude) = (t, a);
        }
    }

    // Lengths, two per instruction: the shear force (for the stresses and
    // the damping) and, with damping, the slip speed the damping opposes.
    let (shear, damping) = (F & SHEAR != 0, F & DAMPING != 0);
    let (shear_magnitude, slip_speed) = norms(shear_force, shear, slip, shear && damping);
    let (sigma, tau) = section_stresses(
        normal_force,
        shear_magnitude,
        twist_magnitude,
        bend_magnitude,
        inv_rb,
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
        // The (smooth) unit vectors of the slip and of the bending spin: one
        // reciprocal each, both in one instruction.
        let spin_across = if bend { w_across.norm() } else { 0.0 };
        let scale_s = unit_scale(slip_speed, ve, smooth);
        let scale_b = unit_scale(spin_across, we, smooth);
        let (inv_s, inv_b) = reciprocals(scale_s, shear, scale_b, bend);
        if shear {
            let direction = reciprocal_unit(slip, scale_s, inv_s);
            shear_force = damp_along(shear_force, shear_magnitude, p.eta_ft, direction);
        }
        if twist {
            // w_along = n (w . n), so its unit vector is n sgn(w . n) (and
            // the smooth one n clamp(w . n / we, -1, 1), the same thing).
            let direction = n * sign(spin_rate, we, smooth);
            twist_torque = damp_along(twist_torque, twist_magnitude, p.eta_tn, direction);
        }
        if bend {
            let direction = reciprocal_unit(w_across, scale_b, inv_b);
            bend_torque = damp_along(bend_torque, bend_magnitude, p.eta_tt, direction);
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

fn scattered<const F: u32>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [&mut BondState],
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
    const SCATTERED: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(scattered::<N>,)*];
});

pub fn single_kernel(features: u32) -> Kernel {
    SINGLE[features as usize % FEATURE_COMBINATIONS]
}

pub fn batch_kernel(features: u32) -> BatchKernel {
    BATCH[features as usize % FEATURE_COMBINATIONS]
}

pub fn scattered_kernel(features: u32) -> ScatteredKernel {
    SCATTERED[features as usize % FEATURE_COMBINATIONS]
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

    /// [`Self::step_batch`] for states that lie apart in memory (in an
    /// engine's contact history): one call per pass of the pair loop, and
    /// the same results, bit for bit, as one [`Self::step`] per bond.
    pub fn step_scattered(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        (self.scattered)(self, kin, dt, states, outs)
    }
}
