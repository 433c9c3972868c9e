//! Critical time-step estimate of a bond: the shortest `2/omega` over its
//! modes, each with the stiffest slope of its hysteresis loop. Percentage
//! damping is not viscous and does not enter the limit.

use super::kernel::{BEND, COMPRESSION, SHEAR, TENSION, TWIST};
use super::model::BondModel;
use super::section::section;
use crate::stability::{oscillator_limit, sphere_inertia};

/// Compression the estimate assumes when the square root is not regularised
/// (its stiffness is unbounded at zero compression), as a fraction of `rb`.
pub const REFERENCE_COMPRESSION: f64 = 1e-3;

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
            dt = dt.min(oscillator_limit(i_eff, self.twist.max_slope() * sec.polar, 0.0));
        }
        if f & BEND != 0 {
            dt = dt.min(oscillator_limit(i_eff, self.bend.max_slope() * sec.inertia, 0.0));
        }
        dt
    }
}
