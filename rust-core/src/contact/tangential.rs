//! Cundall-Strack tangential history.

use crate::vector::{tangential_part, Vec3};

/// Turns the stored spring into the current tangent plane, keeping its
/// length (the contact frame has rotated since the last step).
#[inline(always)]
pub fn carry_spring(spring: Vec3, n: Vec3) -> Vec3 {
    let projected = tangential_part(spring, n);
    let before = spring.norm_squared();
    let after = projected.norm_squared();
    if after > 0.0 {
        projected * (before / after).sqrt()
    } else {
        projected
    }
}
