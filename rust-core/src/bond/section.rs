//! Cross-section of the bond cylinder (spec eq. 2-3) and where along the
//! centre line the bond's contact point sits.

use super::lanes::div2;

/// `rb = lambda min(R_i, R_j)`, `A = pi rb^2`, `J = A rb^2 / 2`, `I = J / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    pub rb: f64,
    pub area: f64,
    pub polar: f64,
    pub inertia: f64,
}

#[inline(always)]
pub fn section(lambda: f64, radius_i: f64, radius_j: f64) -> Section {
    let rb = lambda * radius_i.min(radius_j);
    let area = std::f64::consts::PI * rb * rb;
    let polar = 0.5 * area * rb * rb;
    Section {
        rb,
        area,
        polar,
        inertia: 0.5 * polar,
    }
}

/// `(1 / rb, 1 / (R_i + R_j))`, in one two-lane division: everything per
/// bond that divides by a length of the section (the stresses, see
/// [`super::breakage::section_stresses`]) or by the radii (the lever arms,
/// see [`lever_arms_scaled`]) multiplies by these instead.
#[inline(always)]
pub fn reciprocals(sec: &Section, radius_i: f64, radius_j: f64) -> (f64, f64) {
    div2(1.0, sec.rb, 1.0, radius_i + radius_j)
}

/// Distances from the centres of `i` and `j` to the contact point, which
/// divides `r` in the ratio of the radii: `rc_i = r R_i / (R_i + R_j)`.
#[inline(always)]
pub fn lever_arms(r: f64, radius_i: f64, radius_j: f64) -> (f64, f64) {
    lever_arms_scaled(r, 1.0 / (radius_i + radius_j), radius_i, radius_j)
}

/// [`lever_arms`] given `inv_radius_sum = 1 / (R_i + R_j)`.
#[inline(always)]
pub fn lever_arms_scaled(r: f64, inv_radius_sum: f64, radius_i: f64, radius_j: f64) -> (f64, f64) {
    let s = r * inv_radius_sum;
    (s * radius_i, s * radius_j)
}
