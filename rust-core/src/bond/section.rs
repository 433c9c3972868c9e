//! Cross-section of the bond cylinder (docs/models/bond-nonlinear.md eq. 2-3) and where along the
//! centre line the bond's contact point sits.

use crate::real::Real;

/// `rb = lambda min(R_i, R_j)`, `A = pi rb^2`, `J = A rb^2 / 2`, `I = J / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section<R = f64> {
    /// Bond radius `rb = lambda min(R_i, R_j)` (m; eq. 2).
    pub rb: R,
    /// Area `A = pi rb^2` (m^2; eq. 3).
    pub area: R,
    /// Polar moment `J = A rb^2 / 2` (m^4; eq. 3), of twisting.
    pub polar: R,
    /// Moment of inertia `I = J / 2` (m^4; eq. 3), of bending.
    pub inertia: R,
}

/// The section of a bond with radius multiplier `lambda` between spheres of
/// radii `radius_i` and `radius_j` (docs/models/bond-nonlinear.md eq. 2-3).
#[inline(always)]
pub fn section<R: Real>(lambda: f64, radius_i: R, radius_j: R) -> Section<R> {
    let half = R::splat(0.5);
    let rb = R::splat(lambda) * radius_i.min(radius_j);
    let area = R::splat(std::f64::consts::PI) * rb * rb;
    let polar = half * area * rb * rb;
    Section {
        rb,
        area,
        polar,
        inertia: half * polar,
    }
}

/// `(1 / rb, 1 / (R_i + R_j))`, in one two-lane division: everything per
/// bond that divides by a length of the section (the stresses, see
/// [`super::breakage::section_stresses`]) or by the radii (the lever arms,
/// see [`lever_arms_scaled`]) multiplies by these instead.
#[inline(always)]
pub fn reciprocals<R: Real>(sec: &Section<R>, radius_i: R, radius_j: R) -> (R, R) {
    let one = R::splat(1.0);
    R::div2(one, sec.rb, one, radius_i + radius_j)
}

/// Distances from the centres of `i` and `j` to the contact point, which
/// divides `r` in the ratio of the radii: `rc_i = r R_i / (R_i + R_j)`,
/// given `inv_radius_sum = 1 / (R_i + R_j)`.
#[inline(always)]
pub fn lever_arms_scaled<R: Real>(r: R, inv_radius_sum: R, radius_i: R, radius_j: R) -> (R, R) {
    let s = r * inv_radius_sum;
    (s * radius_i, s * radius_j)
}
