//! Normal spring-dashpot: `Fn = k_n delta_n - gamma_n v_n`.

/// `v_n = (v_i - v_j) . n` is positive when the spheres separate.
#[inline(always)]
pub fn normal_force(k_n: f64, gamma_n: f64, overlap: f64, v_n: f64, no_attraction: bool) -> f64 {
    let f = k_n * overlap - gamma_n * v_n;
    if no_attraction {
        f.max(0.0)
    } else {
        f
    }
}
