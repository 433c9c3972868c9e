//! Normal force of the bond: square-root law in compression, linear in
//! tension, six branches with load history (docs/models/bond-nonlinear.md eq. 4-6).

use super::hysteresis::{select, update_extremes, Loop};
use crate::real::Real;

/// The six-branch normal law of one bond type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalLaw {
    /// The loop of the compression side, on `s(delta)` (`k_fn1`, `ku_fn1`,
    /// `kc_fn1`).
    pub compression: Loop,
    /// The loop of the tension side, on `-delta` (`k_fn2`, `ku_fn2`, `kc_fn2`).
    pub tension: Loop,
    /// `delta_eps`: below it the square root is continued linearly (0 = off).
    pub linear_below: f64,
    /// `1 / sqrt(delta_eps)`, the slope of that linear continuation.
    inv_sqrt_eps: f64,
    /// LIGGGHTS-INL's history rule (`historyReset`): `delta_max` is zeroed in
    /// tension and `delta_min` in compression; off, both last the bond's life.
    pub history_reset: bool,
}

impl NormalLaw {
    /// The law of the two loops, continued linearly below `linear_below`
    /// (`delta_eps`, m; 0 = off).
    pub fn new(compression: Loop, tension: Loop, linear_below: f64, history_reset: bool) -> Self {
        let inv_sqrt_eps = if linear_below > 0.0 {
            1.0 / linear_below.sqrt()
        } else {
            0.0
        };
        Self {
            compression,
            tension,
            linear_below,
            inv_sqrt_eps,
            history_reset,
        }
    }

    /// `s(delta)`: `sqrt(delta)`, or `delta / sqrt(delta_eps)` below
    /// `delta_eps` (continuous at `delta_eps`, finite slope at 0).
    #[inline(always)]
    pub fn root<R: Real>(&self, delta: R) -> R {
        self.continued(delta, delta.sqrt())
    }

    /// [`Self::root`] given `sqrt(delta)` (so two can share an instruction).
    #[inline(always)]
    fn continued<R: Real>(&self, delta: R, root: R) -> R {
        select(
            delta.lt(R::splat(self.linear_below)),
            delta * R::splat(self.inv_sqrt_eps),
            root,
        )
    }

    /// docs/models/bond-nonlinear.md eq. 4, applied before the law so
    /// `delta_min <= delta <= delta_max` (see [`update_extremes`]).
    #[inline(always)]
    pub fn update_history<R: Real>(&self, delta: R, delta_max: R, delta_min: R) -> (R, R) {
        update_extremes(delta, delta_max, delta_min, self.history_reset)
    }

    /// Normal stress `Fn / A` (positive = repulsive) for an up-to-date history.
    /// `tension` / `compression` switch the halves of the law off; kernels
    /// pass constants, so the switched-off half is compiled out. Both halves
    /// are evaluated and the one for the sign of `delta` is selected without
    /// a jump (the sign varies from bond to bond; see [`select`]).
    #[inline(always)]
    pub fn stress<R: Real>(
        &self,
        delta: R,
        delta_max: R,
        delta_min: R,
        tension: bool,
        compression: bool,
    ) -> R {
        let zero = R::splat(0.0);
        let pushed = if compression {
            // Both square roots in one instruction; the same bits as `root`.
            let (sd, sm) = R::sqrt2(delta, delta_max);
            self.compression
                .value(self.continued(delta, sd), self.continued(delta_max, sm))
        } else {
            zero
        };
        let pulled = if tension {
            -self.tension.value(-delta, -delta_min)
        } else {
            zero
        };
        select(delta.ge(zero), pushed, pulled)
    }
}
