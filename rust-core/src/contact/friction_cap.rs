//! The Coulomb-type cap shared by the tangential spring and the rolling
//! spring: a trial load `-k x - gamma v` is limited to `limit` in magnitude,
//! keeping its direction, and the spring is reset to be consistent with the
//! capped load so it cannot grow without bound while slipping.

use super::vectors::ContactVector;

/// Returns the (possibly capped) load, the spring elongation to store and
/// whether the cap was hit.
#[inline(always)]
pub fn capped_spring<V: ContactVector>(
    elongation: V,
    rate: V,
    k: f64,
    gamma: f64,
    limit: f64,
) -> (V, V, bool) {
    let trial = -(elongation * k) - rate * gamma;
    // squares compared (limit >= 0): a load within the cap, the common
    // case, waits for no square root
    let magnitude2 = trial.norm_squared();
    if magnitude2 <= limit * limit {
        return (trial, elongation, false);
    }
    let load = trial * (limit / magnitude2.sqrt());
    let reset = if k > 0.0 {
        -(load + rate * gamma) / k
    } else {
        elongation
    };
    (load, reset, true)
}
