//! A validated Voigt contact type and its step.

use super::friction_cap::capped_spring;
use super::normal::normal_force;
use super::params::VoigtParams;
use super::rolling::{effective_radius, rolling_spin};
use super::state::{ContactOutput, ContactState};
use super::tangential::carry_spring;
use crate::kinematics::{centre_line, slip_velocity, KinematicsError, PairKinematics};
use crate::parameters::ParameterError;
use crate::stability::{oscillator_limit, sphere_inertia};
use crate::vector::{tangential_part, v3, Vec3};

/// Where and how deep two bodies touch, and how far from each centre the
/// contact point lies.
#[derive(Clone, Copy, Debug)]
pub struct ContactGeometry {
    /// Unit normal from `j` to `i`.
    pub n: Vec3,
    /// `delta_n > 0` when touching.
    pub overlap: f64,
    pub lever_i: f64,
    pub lever_j: f64,
    /// `R*` of the rolling cap.
    pub r_eff: f64,
}

/// Velocities of the two bodies.
#[derive(Clone, Copy, Debug)]
pub struct BodyVelocities {
    pub v_i: Vec3,
    pub v_j: Vec3,
    pub w_i: Vec3,
    pub w_j: Vec3,
}

/// A plane wall: a point on it, its unit normal towards the particles, and
/// its velocity (walls do not spin).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub velocity: [f64; 3],
}

pub fn sphere_sphere(kin: &PairKinematics) -> Result<(ContactGeometry, BodyVelocities), KinematicsError> {
    kin.check()?;
    let line = centre_line(kin)?;
    let geometry = ContactGeometry {
        n: line.n,
        overlap: kin.radius_i + kin.radius_j - line.r,
        lever_i: kin.radius_i,
        lever_j: kin.radius_j,
        r_eff: effective_radius(kin.radius_i, Some(kin.radius_j)),
    };
    let velocities = BodyVelocities {
        v_i: v3(kin.v_i),
        v_j: v3(kin.v_j),
        w_i: v3(kin.w_i),
        w_j: v3(kin.w_j),
    };
    Ok((geometry, velocities))
}

pub fn sphere_plane(
    x_i: [f64; 3],
    v_i: [f64; 3],
    w_i: [f64; 3],
    radius_i: f64,
    plane: &Plane,
) -> (ContactGeometry, BodyVelocities) {
    let n = v3(plane.normal);
    let gap = (v3(x_i) - v3(plane.point)).dot(&n);
    let geometry = ContactGeometry {
        n,
        overlap: radius_i - gap,
        lever_i: radius_i,
        lever_j: 0.0,
        r_eff: effective_radius(radius_i, None),
    };
    let velocities = BodyVelocities {
        v_i: v3(v_i),
        v_j: v3(plane.velocity),
        w_i: v3(w_i),
        w_j: Vec3::zeros(),
    };
    (geometry, velocities)
}

#[derive(Clone, Debug)]
pub struct VoigtModel {
    pub params: VoigtParams,
    no_attraction: bool,
    rolling: bool,
}

impl VoigtModel {
    pub fn new(params: VoigtParams) -> Result<Self, ParameterError> {
        params.validate()?;
        Ok(Self {
            params,
            no_attraction: params.no_attraction != 0,
            rolling: params.rolling != 0,
        })
    }

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
        let (g, v) = sphere_sphere(kin)?;
        self.step_geometry(&g, &v, dt, state, out);
        Ok(())
    }

    /// One step of any contact, given its geometry. Apart spheres exert
    /// nothing and forget their history.
    #[inline]
    pub fn step_geometry(
        &self,
        g: &ContactGeometry,
        v: &BodyVelocities,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) {
        if self.rolling {
            self.kernel::<true>(g, v, dt, state, out)
        } else {
            self.kernel::<false>(g, v, dt, state, out)
        }
    }

    #[inline(always)]
    fn kernel<const ROLLING: bool>(
        &self,
        g: &ContactGeometry,
        v: &BodyVelocities,
        dt: f64,
        state: &mut ContactState,
        out: &mut ContactOutput,
    ) {
        *out = ContactOutput {
            overlap: g.overlap,
            ..ContactOutput::default()
        };
        if !(g.overlap > 0.0) {
            *state = ContactState::default();
            return;
        }
        let p = &self.params;
        let n = g.n;
        let v_rel = v.v_i - v.v_j;
        let f_n = normal_force(p.k_n, p.gamma_n, g.overlap, v_rel.dot(&n), self.no_attraction);

        let slip = slip_velocity(v_rel, v.w_i, v.w_j, n, g.lever_i, g.lever_j);
        let spring = carry_spring(v3(state.tangential_spring), n) + slip * dt;
        let (f_t, spring, sliding) = capped_spring(spring, slip, p.k_t, p.gamma_t, p.mu * f_n.abs());
        state.tangential_spring = spring.into();

        let arm = n.cross(&f_t);
        let mut torque_i = -arm * g.lever_i;
        let mut torque_j = -arm * g.lever_j;
        if ROLLING {
            let spin = rolling_spin(v.w_i, v.w_j, n);
            let angle = tangential_part(v3(state.rolling_angle), n) + spin * dt;
            let limit = p.mu_r * f_n.abs() * g.r_eff;
            let (t_r, angle, rolling_slip) = capped_spring(angle, spin, p.k_r, p.gamma_r, limit);
            state.rolling_angle = angle.into();
            let t_r = t_r - spin * p.eta_r;
            torque_i += t_r;
            torque_j -= t_r;
            out.rolling_slip = rolling_slip as i32;
        }
        out.force_i = (n * f_n + f_t).into();
        out.torque_i = torque_i.into();
        out.torque_j = torque_j.into();
        out.normal_force = f_n;
        out.touching = 1;
        out.sliding = sliding as i32;
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
}
