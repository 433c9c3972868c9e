//! A validated Voigt contact type and its step.

use super::frame::{sphere_sphere, ContactFrame, FrameIn};
use super::friction_cap::capped_spring;
use super::normal::normal_force;
use super::params::VoigtParams;
use super::rolling::rolling_spin;
use super::state::{ContactOutput, ContactState};
use super::tangential::carry_spring;
use super::vectors::ContactVector;
use crate::kinematics::{slip_velocity, KinematicsError, PairKinematics};
use crate::parameters::ParameterError;
use crate::stability::{oscillator_limit, sphere_inertia, RECOMMENDED_FRACTION};
use crate::vector::{tangential_part, v3, Vec3};

/// Tangential load of one step: the force on `i` and the torques its couple
/// puts on both bodies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentialLoad<V = Vec3> {
    /// Tangential force on `i` (N), at most `mu |Fn|`.
    pub force: V,
    /// Torque of that force on `i` (N m).
    pub torque_i: V,
    /// Torque of that force on `j` (N m).
    pub torque_j: V,
    /// The force sits on the Coulomb cap.
    pub sliding: bool,
}

/// The loads of one step of touching bodies, as the laws' vectors `V`.
#[derive(Clone, Copy)]
pub(crate) struct Loads<V> {
    pub force_i: V,
    pub torque_i: V,
    pub torque_j: V,
    pub normal_force: f64,
    pub sliding: bool,
    pub rolling_slip: bool,
}

/// A validated Voigt contact type (docs/models/voigt.md) and its step;
/// `GbVoigtModel` in the C ABI.
#[derive(Clone, Debug)]
pub struct VoigtModel {
    /// The parameters, validated. The switches `no_attraction` and `rolling`
    /// are read once, by [`Self::new`].
    pub params: VoigtParams,
    no_attraction: bool,
    rolling: bool,
}

impl VoigtModel {
    /// Validates `params` and builds the contact type; the error names the
    /// first parameter refused.
    pub fn new(params: VoigtParams) -> Result<Self, ParameterError> {
        params.validate()?;
        Ok(Self {
            params,
            no_attraction: params.no_attraction != 0,
            rolling: params.rolling != 0,
        })
    }

    /// Whether rolling resistance is on.
    pub fn rolling(&self) -> bool {
        self.rolling
    }

    /// One step of a sphere-sphere contact.
    #[inline]
    pub fn step(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) -> Result<(), KinematicsError> {
        if self.rolling {
            self.step_pair::<true>(kin, dt, state, out)
        } else {
            self.step_pair::<false>(kin, dt, state, out)
        }
    }

    /// [`Self::step`] over equal-length slices, with the rolling switch
    /// decided once for the whole batch; stops at the first bad input and
    /// reports its index.
    pub fn step_batch(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [ContactState],
        outs: &mut [ContactOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        if self.rolling {
            self.batch::<true>(kin, dt, states, outs)
        } else {
            self.batch::<false>(kin, dt, states, outs)
        }
    }

    fn batch<const ROLLING: bool>(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [ContactState],
        outs: &mut [ContactOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        for (index, ((k, s), o)) in kin.iter().zip(states.iter_mut()).zip(outs.iter_mut()).enumerate() {
            self.step_pair::<ROLLING>(k, dt, s, o).map_err(|e| (index, e))?;
        }
        Ok(())
    }

    /// The sphere-sphere step with rolling resistance on or off at compile
    /// time; the frame is built in place and not kept.
    #[inline(always)]
    fn step_pair<const ROLLING: bool>(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) -> Result<(), KinematicsError> {
        self.step_frame_kernel::<ROLLING>(&sphere_sphere(kin)?, dt, state, out);
        Ok(())
    }

    /// One step of any contact. Bodies apart exert nothing and forget their
    /// history. The engines' per-contact calls (`contact::dispatch`) run the
    /// same laws (`VoigtModel::touching`) on their own vectors. Dispatches once
    /// on the rolling switch to [`Self::step_frame_kernel`].
    #[inline(always)]
    pub fn step_frame(&self, f: &ContactFrame, dt: f64, state: &mut ContactState, out: &mut ContactOutput) {
        if self.rolling {
            self.step_frame_kernel::<true>(f, dt, state, out)
        } else {
            self.step_frame_kernel::<false>(f, dt, state, out)
        }
    }

    /// [`Self::step_frame`] with rolling resistance switched at compile time
    /// (`ROLLING` must equal [`Self::rolling`]; a caller that loops over many
    /// contacts decides it once, outside the loop). Without rolling, the
    /// rolling part is compiled out.
    #[inline(always)]
    pub fn step_frame_kernel<const ROLLING: bool>(
        &self,
        f: &ContactFrame,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) {
        self.frame_kernel::<ROLLING, true>(f, dt, state, out)
    }

    /// The loads of a contact from its stored state, which is not advanced:
    /// the springs are turned into the current plane but get no increment
    /// (stock `pair granular` and LIGGGHTS do the same). This is what the setup
    /// pass of a run applies: in the frame and with the velocities of the
    /// last step, the loads that step applied (without dashpots and below
    /// the caps; turning a spring already in the plane changes at most its
    /// last bits), so a continued or restarted run starts from the same
    /// forces as an uninterrupted one.
    pub fn evaluate_frame(&self, f: &ContactFrame, state: &ContactState, out: &mut ContactOutput) {
        let mut scratch = *state;
        if self.rolling {
            self.frame_kernel::<true, false>(f, 0.0, &mut scratch, out)
        } else {
            self.frame_kernel::<false, false>(f, 0.0, &mut scratch, out)
        }
    }

    #[inline(always)]
    fn frame_kernel<const ROLLING: bool, const ADVANCE: bool>(
        &self,
        f: &ContactFrame,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) {
        debug_assert_eq!(ROLLING, self.rolling);
        *out = ContactOutput {
            overlap: f.overlap,
            ..ContactOutput::default()
        };
        let (mut spring, mut angle) = (v3(state.tangential_spring), v3(state.rolling_angle));
        let Some(l) = self.touching::<Vec3, ROLLING, ADVANCE>(&f.vectors(), dt, &mut spring, &mut angle)
        else {
            *state = ContactState::default();
            return;
        };
        state.tangential_spring = spring.into();
        if ROLLING {
            state.rolling_angle = angle.into();
            out.rolling_slip = l.rolling_slip as i32;
        }
        out.force_i = l.force_i.into();
        out.torque_i = l.torque_i.into();
        out.torque_j = l.torque_j.into();
        out.normal_force = l.normal_force;
        out.touching = 1;
        out.sliding = l.sliding as i32;
    }

    /// The laws of one step, on any of their vectors (`contact::dispatch`
    /// runs them on AVX registers): `None` when the bodies are apart (the
    /// caller forgets the history), else the loads, with the tangential
    /// spring and (with `ROLLING`) the rolling angle updated in place.
    #[inline(always)]
    pub(crate) fn touching<V: ContactVector, const ROLLING: bool, const ADVANCE: bool>(
        &self,
        f: &FrameIn<V>,
        dt: f64,
        spring: &mut V,
        angle: &mut V,
    ) -> Option<Loads<V>> {
        if !(f.overlap > 0.0) {
            return None;
        }
        let f_n = self.normal_force_in(f);
        let t = self.tangential_kernel::<V, ADVANCE>(f, f_n, dt, spring);
        let (mut torque_i, mut torque_j) = (t.torque_i, t.torque_j);
        let mut rolling_slip = false;
        if ROLLING {
            let (t_r, slip) = self.rolling_kernel::<V, ADVANCE>(f, f_n, dt, angle);
            torque_i = torque_i + t_r;
            torque_j -= t_r;
            rolling_slip = slip;
        }
        Some(Loads {
            force_i: f.n * f_n + t.force,
            torque_i,
            torque_j,
            normal_force: f_n,
            sliding: t.sliding,
            rolling_slip,
        })
    }

    /// `Fn = k_n delta_n - gamma_n v_n` (clamped at zero without attraction).
    #[inline(always)]
    pub fn normal_force(&self, f: &ContactFrame) -> f64 {
        self.normal_force_in(&f.vectors())
    }

    #[inline(always)]
    fn normal_force_in<V: ContactVector>(&self, f: &FrameIn<V>) -> f64 {
        let v_n = (f.v_i - f.v_j).dot(&f.n);
        normal_force(
            self.params.k_n,
            self.params.gamma_n,
            f.overlap,
            v_n,
            self.no_attraction,
        )
    }

    /// Cundall-Strack spring with the Coulomb cap `mu |Fn|`; updates the
    /// spring elongation in place.
    #[inline(always)]
    pub fn tangential(&self, f: &ContactFrame, f_n: f64, dt: f64, spring: &mut [f64; 3]) -> TangentialLoad {
        let mut s = v3(*spring);
        let t = self.tangential_kernel::<Vec3, true>(&f.vectors(), f_n, dt, &mut s);
        *spring = s.into();
        t
    }

    /// [`Self::tangential`] of the stored spring, not advanced (see
    /// [`Self::evaluate_frame`]).
    pub fn tangential_held(&self, f: &ContactFrame, f_n: f64, spring: &[f64; 3]) -> TangentialLoad {
        let mut scratch = v3(*spring);
        self.tangential_kernel::<Vec3, false>(&f.vectors(), f_n, 0.0, &mut scratch)
    }

    #[inline(always)]
    fn tangential_kernel<V: ContactVector, const ADVANCE: bool>(
        &self,
        f: &FrameIn<V>,
        f_n: f64,
        dt: f64,
        spring: &mut V,
    ) -> TangentialLoad<V> {
        let p = &self.params;
        let n = f.n;
        let slip = slip_velocity(f.v_i - f.v_j, f.w_i, f.w_j, n, f.lever_i, f.lever_j);
        let carried = carry_spring(*spring, n);
        let trial = if ADVANCE { carried + slip * dt } else { carried };
        let (force, kept, sliding) = capped_spring(trial, slip, p.k_t, p.gamma_t, p.mu * f_n.abs());
        *spring = kept;
        let arm = n.cross(&force);
        TangentialLoad {
            force,
            torque_i: -arm * f.lever_i,
            torque_j: -arm * f.lever_j,
            sliding,
        }
    }

    /// Iwashita-Oda rolling torque on `i` (`-` of it on `j`): spring and
    /// dashpot capped at `mu_r |Fn| R*`, plus the uncapped viscous term.
    /// Updates the rolling angle in place; reports whether the cap was hit.
    #[inline(always)]
    pub fn rolling_torque(&self, f: &ContactFrame, f_n: f64, dt: f64, angle: &mut [f64; 3]) -> (Vec3, bool) {
        let mut a = v3(*angle);
        let t = self.rolling_kernel::<Vec3, true>(&f.vectors(), f_n, dt, &mut a);
        *angle = a.into();
        t
    }

    /// [`Self::rolling_torque`] of the stored angle, not advanced (see
    /// [`Self::evaluate_frame`]).
    pub fn rolling_torque_held(&self, f: &ContactFrame, f_n: f64, angle: &[f64; 3]) -> (Vec3, bool) {
        let mut scratch = v3(*angle);
        self.rolling_kernel::<Vec3, false>(&f.vectors(), f_n, 0.0, &mut scratch)
    }

    #[inline(always)]
    fn rolling_kernel<V: ContactVector, const ADVANCE: bool>(
        &self,
        f: &FrameIn<V>,
        f_n: f64,
        dt: f64,
        angle: &mut V,
    ) -> (V, bool) {
        let p = &self.params;
        let n = f.n;
        let spin = rolling_spin(f.w_i, f.w_j, n);
        let turned = tangential_part(*angle, n);
        let trial = if ADVANCE { turned + spin * dt } else { turned };
        let limit = p.mu_r * f_n.abs() * f.r_eff;
        let (t_r, kept, slip) = capped_spring(trial, spin, p.k_r, p.gamma_r, limit);
        *angle = kept;
        (t_r - spin * p.eta_r, slip)
    }

    /// Critical step between spheres of the given radii and masses: normal
    /// (reduced mass, with its dashpot), tangential (reduced mass plus the
    /// rotation of each sphere about its centre) and rolling (reduced moment
    /// of inertia).
    pub fn critical_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let p = &self.params;
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let (ii, ij) = (sphere_inertia(mass_i, radius_i), sphere_inertia(mass_j, radius_j));
        let mobility = 1.0 / mass_i + 1.0 / mass_j + radius_i * radius_i / ii + radius_j * radius_j / ij;
        let mut dt =
            oscillator_limit(m_eff, p.k_n, p.gamma_n).min(oscillator_limit(1.0 / mobility, p.k_t, p.gamma_t));
        if self.rolling {
            let i_eff = ii * ij / (ii + ij);
            dt = dt.min(oscillator_limit(i_eff, p.k_r, p.gamma_r + p.eta_r));
        }
        dt
    }

    /// [`RECOMMENDED_FRACTION`] of [`VoigtModel::critical_timestep`]: the
    /// step above which the engines warn.
    pub fn recommended_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        RECOMMENDED_FRACTION * self.critical_timestep(radius_i, radius_j, mass_i, mass_j)
    }
}
