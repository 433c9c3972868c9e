//! Critical time-step estimate of a bond: the shortest `2/omega` over its
//! modes, each with the stiffest slope of its hysteresis loop. Percentage
//! damping is not viscous and does not enter the limit.

use super::features::{BEND, COMPRESSION, SHEAR, TENSION, TWIST};
use super::model::BondModel;
use super::section::section;
use crate::stability::{oscillator_limit, sphere_inertia};

/// Compression the estimate assumes when the square root is not regularised
/// (its stiffness is unbounded at zero compression), as a fraction of `rb`.
pub const REFERENCE_COMPRESSION: f64 = 1e-3;

pub use crate::stability::RECOMMENDED_FRACTION;

impl BondModel {
    /// Critical step of this bond type between spheres of the given radii and
    /// masses. Modes: axial (reduced mass), shear (reduced mass plus the
    /// rotation each sphere takes about its own centre), twisting and bending
    /// (reduced moment of inertia). The square-root branch is evaluated at
    /// `compression_linear_below`, or at [`REFERENCE_COMPRESSION`]`* rb`
    /// when that is off.
    pub fn critical_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let p = &self.params;
        let f = self.features;
        let sec = section(p.lambda, radius_i, radius_j);
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let (inertia_i, inertia_j) = (sphere_inertia(mass_i, radius_i), sphere_inertia(mass_j, radius_j));
        let i_eff = inertia_i * inertia_j / (inertia_i + inertia_j);
        let mut dt = f64::INFINITY;
        if f & TENSION != 0 {
            dt = dt.min(oscillator_limit(
                m_eff,
                self.normal.tension.max_slope() * sec.area,
                0.0,
            ));
        }
        if f & COMPRESSION != 0 {
            let d_ref = if p.compression_linear_below > 0.0 {
                p.compression_linear_below
            } else {
                REFERENCE_COMPRESSION * sec.rb
            };
            // d/dd of k sqrt(d) is k / (2 sqrt d); the linear continuation has
            // slope k / sqrt(eps), the larger of the two at eps.
            let slope = if p.compression_linear_below > 0.0 {
                1.0
            } else {
                0.5
            } / d_ref.sqrt();
            dt = dt.min(oscillator_limit(
                m_eff,
                self.normal.compression.max_slope() * slope * sec.area,
                0.0,
            ));
        }
        if f & SHEAR != 0 {
            let (ri, rj) = (radius_i, radius_j); // lever arms at r = R_i + R_j
            let mobility = 1.0 / mass_i + 1.0 / mass_j + ri * ri / inertia_i + rj * rj / inertia_j;
            dt = dt.min(oscillator_limit(1.0 / mobility, p.k_ft * sec.area, 0.0));
        }
        if f & TWIST != 0 {
            dt = dt.min(oscillator_limit(
                i_eff,
                self.twist.hysteresis.max_slope() * sec.polar,
                0.0,
            ));
        }
        if f & BEND != 0 {
            dt = dt.min(oscillator_limit(
                i_eff,
                self.bend.hysteresis.max_slope() * sec.inertia,
                0.0,
            ));
        }
        dt
    }
}

impl BondModel {
    /// [`RECOMMENDED_FRACTION`] of [`BondModel::critical_timestep`]: the step
    /// to use, and the one above which the engines warn.
    pub fn recommended_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        RECOMMENDED_FRACTION * self.critical_timestep(radius_i, radius_j, mass_i, mass_j)
    }

    /// Compression below which the plain square root (no
    /// `compression_linear_below`) is not integrated at step `dt` but
    /// rattles. Its local stiffness `k_n1 A / (2 sqrt d)` reaches the limit
    /// `4 m_eff / dt^2` at `d_c = (k A dt^2 / (8 m_eff))^2` (`k` the stiffest
    /// compression slope); a bond left below `d_c` gains energy from round-off
    /// until it rattles with an amplitude of 2-4 `d_c` (measured, elastic and
    /// hysteretic, docs/speed-accuracy.md), then stays bounded. This returns
    /// `16 d_c`, where the local step is half the local limit: compressions
    /// above it are resolved, below it they are noise of at most this size.
    /// Zero when the law is regularised (`compression_linear_below > 0`:
    /// bounded stiffness, which [`BondModel::critical_timestep`] covers) or
    /// compression is off.
    pub fn compression_noise_floor(
        &self,
        dt: f64,
        radius_i: f64,
        radius_j: f64,
        mass_i: f64,
        mass_j: f64,
    ) -> f64 {
        if self.features & COMPRESSION == 0 || self.params.compression_linear_below > 0.0 {
            return 0.0;
        }
        let sec = section(self.params.lambda, radius_i, radius_j);
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let root = self.normal.compression.max_slope() * sec.area * dt * dt / (8.0 * m_eff);
        16.0 * root * root
    }
}
