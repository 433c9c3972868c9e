//! Twisting and bending torques (docs/models/bond-nonlinear.md, "Twisting
//! and bending"): accumulated relative rotations about and across the bond
//! axis, each with a signed, two-sided hysteresis loop, every side with its
//! own history extreme (as `delta_max` / `delta_min` for the normal force).
//!
//! Twisting is one-dimensional: the signed angle `phi = theta_n . n` with
//! `phi_max >= 0` and `phi_min <= 0`. Bending happens in a plane that can
//! turn, so its sides are defined by the history itself: the vector `beta`
//! is the extreme reached on the *leading* side (its direction says which
//! side that is), the scalar `beta_opp` the extreme reached on the
//! *opposite* side. The bending torque is the gradient of the two sides'
//! energies blended by the cosine between the angle and `beta`, so it does
//! no work over a closed path at a fixed history; only dot products and
//! lengths enter, so the law does not depend on the coordinate axes; for
//! bending in a fixed plane it is the signed twisting law along that
//! plane's axis.

use super::hysteresis::{select, update_extremes, Loop};
use crate::real::Real;
use crate::vector::{tangential_part, Vector};

/// Splits the relative angular velocity into its part along `n` (twisting)
/// and across it (bending); also returns `w_rel . n`, whose magnitude is the
/// length of the part along `n` (no square root needed).
#[inline(always)]
pub fn split_relative_spin<R: Real, V: Vector<R>>(w_rel: V, n: V) -> (V, V, R) {
    let rate = w_rel.dot(&n);
    let along = n * rate;
    (along, w_rel - along, rate)
}

/// Twisting angle: kept parallel to the current axis, then advanced.
#[inline(always)]
pub fn advance_twist<R: Real, V: Vector<R>>(theta: V, w_along: V, n: V, dt: R) -> V {
    n * theta.dot(&n) + w_along * dt
}

/// Bending angle: kept in the current tangent plane, then advanced.
#[inline(always)]
pub fn advance_bend<R: Real, V: Vector<R>>(theta: V, w_across: V, n: V, dt: R) -> V {
    tangential_part(theta, n) + w_across * dt
}

/// Hysteresis loop of one torque and its history rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TorqueLaw {
    /// The loop `h` of the torque: `k_tn`, `ku_tn`, `kc_tn` for twisting,
    /// `k_tt`, `ku_tt`, `kc_tt` for bending.
    pub hysteresis: Loop,
    /// The history rule of docs/models/bond-nonlinear.md: on
    /// (`historyReset`, LIGGGHTS-INL's code), being on one side forgets the
    /// other side's extreme; off, the extremes last the bond's life.
    pub history_reset: bool,
}

/// A torque on sphere `i`, with `|torque|` known from the law (no square
/// root needed for the stresses and the damping).
#[derive(Clone, Copy, Debug)]
pub struct Torque<R, V> {
    /// The torque on `i` (N m).
    pub torque: V,
    /// Its magnitude (N m).
    pub magnitude: R,
}

/// The twisting history after a step: `phi_max >= 0`, `phi_min <= 0`.
#[derive(Clone, Copy, Debug)]
pub struct TwistHistory<R> {
    /// `phi_max`: the largest twisting angle reached (rad).
    pub max: R,
    /// `phi_min`: the smallest twisting angle reached (rad).
    pub min: R,
}

/// The bending history after a step: `beta` (leading side, in the tangent
/// plane) and `beta_opp >= 0` (opposite side).
#[derive(Clone, Copy, Debug)]
pub struct BendHistory<R, V> {
    /// `beta`: the extreme bending angle of the leading side, whose
    /// direction marks that side (rad).
    pub leading: V,
    /// `beta_opp`: the extreme `|theta_t|` reached on the opposite side (rad).
    pub opposite: R,
}

impl TorqueLaw {
    /// Twisting torque on `i` for the (advanced) angle `theta_n`:
    /// `-f(phi) J n` with `f(phi) = h(phi; phi_max)` for `phi >= 0` and
    /// `-h(-phi; -phi_min)` below. The history is updated before the law.
    #[inline(always)]
    pub fn twist<R: Real, V: Vector<R>>(
        &self,
        theta_n: V,
        n: V,
        history: TwistHistory<R>,
        polar: R,
    ) -> (Torque<R, V>, TwistHistory<R>) {
        let phi = theta_n.dot(&n);
        let (max, min) = update_extremes(phi, history.max, history.min, self.history_reset);
        let positive = phi.ge(R::splat(0.0));
        let h = self.hysteresis.value(phi.abs(), select(positive, max, -min));
        let f = select(positive, h, -h);
        (
            Torque {
                torque: n * (-f * polar),
                magnitude: h.abs() * polar,
            },
            TwistHistory { max, min },
        )
    }

    /// Bending torque on `i` for the (advanced) angle `theta_t`, with the
    /// stored history (`beta` is brought into the current tangent plane
    /// here): the gradient of the bending energy
    /// [`super::energy::bend_work`] at the
    /// updated history, `-I dE/dtheta_t`. Zero for a zero angle.
    ///
    /// The history is updated first (docs/models/bond-nonlinear.md,
    /// "Bending"): on the leading side (`theta_t . beta >= 0`) past
    /// `|beta|`, `beta` turns to `theta_t` when `|theta_t|` is beyond both
    /// extremes, and only grows along its own direction otherwise; on the
    /// opposite side `beta_opp` grows to `|theta_t|`. Each update lowers
    /// the energy at the current angle, so no update releases work.
    #[inline(always)]
    pub fn bend<R: Real, V: Vector<R>>(
        &self,
        theta_t: V,
        n: V,
        history: BendHistory<R, V>,
        inertia: R,
    ) -> (Torque<R, V>, BendHistory<R, V>) {
        let (zero, one, half) = (R::splat(0.0), R::splat(1.0), R::splat(0.5));
        let mut beta = tangential_part(history.leading, n);
        let mut opposite = history.opposite;
        let (x, mut extreme) = R::sqrt2(theta_t.norm_squared(), beta.norm_squared());
        let along = theta_t.dot(&beta);
        let mut leading = along.ge(zero);
        // Read only where both angles are non-zero (NaN elsewhere).
        let mut cosine = along / (x * extreme);
        if self.history_reset {
            // Entering the opposite side makes it the leading side, with a
            // fresh history.
            beta = V::select(leading, beta, theta_t);
            extreme = select(leading, extreme, x);
            opposite = select(leading, opposite, zero);
            cosine = select(leading, cosine, one);
            leading = R::mask(true);
        }
        let grows = leading & x.gt(extreme);
        // (Along `beta` itself turning is growing: the same history.)
        let turns = grows & (x.ge(opposite) | !extreme.gt(zero) | cosine.ge(one));
        beta = V::select(turns, theta_t, V::select(grows, beta * (x / extreme), beta));
        cosine = select(turns, one, cosine).clamp(-1.0, 1.0);
        extreme = select(grows, x, extreme);
        opposite = select(leading, opposite, opposite.max(x));

        let h = &self.hysteresis;
        let (h_lead, h_opp) = (h.value(x, extreme), h.value(x, opposite));
        let spread = half * (h.work(x, extreme) - h.work(x, opposite));
        // E = ((1 + c) E_lead + (1 - c) E_opp) / 2 with c = cosine; its
        // gradient: a radial part, and (E_lead - E_opp)/2 times the
        // gradient of c, (beta/|beta| - c theta_t/x) / x.
        let radial = half * ((one + cosine) * h_lead + (one - cosine) * h_opp);
        let (inv_x, inv_beta) = R::div2(one, x, one, extreme);
        let across = beta * inv_beta - theta_t * (cosine * inv_x);
        // In one plane `across` is zero, exactly so where the plane holds a
        // coordinate axis (`c = +-1` and both unit vectors exact): the torque
        // and its size are then the signed law's, bit for bit.
        let torque = theta_t * (-radial * inertia / x) + across * (-(spread * inv_x) * inertia);
        // Off the line, the norm of the sum: the part across the angle is a
        // small difference of two vectors near the history's line.
        let off_line = across.norm_squared().gt(zero);
        let magnitude = select(off_line, torque.norm(), radial.abs() * inertia);
        // A zero angle has no direction: no torque (the selected-away side
        // is NaN there).
        let on = x.gt(zero);
        (
            Torque {
                torque: V::select(on, torque, V::zeros()),
                magnitude: select(on, magnitude, zero),
            },
            BendHistory {
                leading: beta,
                opposite,
            },
        )
    }
}
