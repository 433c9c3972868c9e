//! Iwashita-Oda rolling resistance on the rolling part of the relative spin.

use crate::vector::{tangential_part, Vector};

/// Relative spin without its twisting part: a pure spin about `n` meets no
/// rolling resistance.
#[inline(always)]
pub fn rolling_spin<V: Vector<f64>>(w_i: V, w_j: V, n: V) -> V {
    tangential_part(w_i - w_j, n)
}

/// `R* = R_i R_j / (R_i + R_j)`; for a wall (`R_j` infinite) pass `None`.
#[inline(always)]
pub fn effective_radius(radius_i: f64, radius_j: Option<f64>) -> f64 {
    match radius_j {
        Some(rj) => radius_i * rj / (radius_i + rj),
        None => radius_i,
    }
}
