//! A validated bond type: the laws built from [`BondParams`], which the step
//! reads.

use super::breakage::{StressLimits, SummedLimits};
use super::features::{features, TENSION};
use super::hysteresis::Loop;
use super::normal_law::NormalLaw;
use super::params::{BondParams, ParameterError};
use super::twist_bend::TorqueLaw;

/// A validated bond type: the laws of docs/models/bond-nonlinear.md with
/// their stiffnesses, history rule and break limits, built once from
/// [`BondParams`].
#[derive(Clone, Debug)]
pub struct BondLaws {
    /// The parameters the laws were built from, validated.
    pub params: BondParams,
    /// The normal force (eq. 4-6).
    pub normal: NormalLaw,
    /// The twisting torque (eq. 9).
    pub twist: TorqueLaw,
    /// The bending torque (eq. 10).
    pub bend: TorqueLaw,
    /// Stress mode: the bond breaks on its section stresses (eq. 14-15);
    /// otherwise on its centre distance (`max_distance`).
    pub stress_break: bool,
    /// The strengths of the stress mode (eq. 15).
    pub limits: StressLimits,
    /// BPM mode: the bond breaks by BPM's summed rule on its loads.
    pub bpm_break: bool,
    /// The critical loads of the BPM mode.
    pub summed: SummedLimits,
    /// Bits of [`super::features`] (`TENSION`, `SHEAR`, ...) compiled in.
    pub features: u32,
    /// LIGGGHTS-INL's code (`inl_compatible`): the step is `bond::inl`'s.
    pub inl: bool,
    /// LIGGGHTS-INL's linear bond (`linear`): the step is `bond::linear`'s.
    pub linear: bool,
}

impl BondLaws {
    /// Validates `params` ([`BondParams::validate`]) and builds the laws; the
    /// error names the first parameter refused.
    pub fn new(params: BondParams) -> Result<Self, ParameterError> {
        params.validate()?;
        let on = BondParams::switch;
        let p = &params;
        let inl = on(p.inl_compatible);
        // INL's code resets the history on every sign change.
        let reset = on(p.history_reset) || inl;
        Ok(Self {
            normal: NormalLaw::new(
                Loop::new(p.k_fn1, p.ku_fn1, p.kc_fn1),
                Loop::new(p.k_fn2, p.ku_fn2, p.kc_fn2),
                p.compression_linear_below,
                reset,
            ),
            twist: TorqueLaw {
                hysteresis: Loop::new(p.k_tn, p.ku_tn, p.kc_tn),
                history_reset: reset,
            },
            bend: TorqueLaw {
                hysteresis: Loop::new(p.k_tt, p.ku_tt, p.kc_tt),
                history_reset: reset,
            },
            stress_break: on(p.stress_break),
            limits: StressLimits {
                max_sigma: p.max_sigma,
                max_tau: p.max_tau,
                tension_factor: if on(p.use_ratio) {
                    p.tension_compression_ratio
                } else {
                    1.0
                },
            },
            bpm_break: on(p.bpm_break),
            summed: SummedLimits {
                normal: p.max_normal_force,
                shear: p.max_shear_force,
                bend: p.max_bend_torque,
                twist: p.max_twist_torque,
            },
            features: features(p),
            inl,
            linear: on(p.linear),
            params,
        })
    }

    /// The limits `(sigma_max, tau_max)` the section stresses of a bond at
    /// compression `delta` are held against (eq. 15): `sigma_max` times
    /// `gamma` while stretched (`delta < 0`) with `use_ratio`; `(0, 0)` in
    /// distance mode, which has none.
    pub fn stress_limits_at(&self, delta: f64) -> (f64, f64) {
        if !self.stress_break {
            return (0.0, 0.0);
        }
        let l = &self.limits;
        let factor = if delta < 0.0 { l.tension_factor } else { 1.0 };
        (l.max_sigma * factor, l.max_tau)
    }

    /// What the compression law's stiffnesses multiply: the section area
    /// `area`, or 1 under `inl_compatible` (LIGGGHTS-INL's compression has
    /// no `A`).
    pub fn compression_area(&self, area: f64) -> f64 {
        if self.inl {
            1.0
        } else {
            area
        }
    }

    /// One line for a run's opening output saying which law runs: the
    /// write-up's (and that LIGGGHTS-INL's code differs from it, with the
    /// switch that follows that code), or LIGGGHTS-INL's code. `switch` is
    /// the name a deck gives `inl_compatible` (`inlCompatible`,
    /// `inl_compatible`).
    pub fn law_line(&self, switch: &str) -> String {
        if self.linear {
            "LIGGGHTS-INL's linear bond (cohesion bond, docs/models/bond-linear.md): linear springs, \
             damping per Cartesian component, the contact's loads kept under an overlapping bond"
                .to_string()
        } else if self.inl {
            format!(
                "LIGGGHTS-INL's code ({switch} on): compression k_fn1 sqrt(d) without the section A, \
                 extremes reset on every sign change, twisting, bending and damping per Cartesian \
                 component, the contact's tangential and rolling loads kept under an overlapping bond"
            )
        } else {
            format!(
                "the law of docs/models/bond-nonlinear.md (compression k_fn1 A sqrt(d), frame-indifferent \
                 twisting, bending and damping, the contact replaced under the bond); LIGGGHTS-INL's \
                 code differs from it, {switch} on follows that code"
            )
        }
    }

    /// Whether the contact's tangential and rolling loads act on an
    /// overlapping pair while its bond is intact, as in LIGGGHTS-INL, whose
    /// bond takes the place of the contact's normal load alone
    /// (`inl_compatible`); otherwise the bond replaces every contact load.
    pub fn keeps_contact_tangential(&self) -> bool {
        self.params.keeps_contact_tangential()
    }

    /// Whether every load of the contact (normal, tangential, rolling) acts
    /// on an overlapping pair while its bond is intact, the bond's loads
    /// added to them, as under LIGGGHTS-INL's linear bond (`linear`).
    pub fn keeps_contact_loads(&self) -> bool {
        self.params.keeps_contact_loads()
    }

    /// Whether the contact's state goes on under an intact bond and acts
    /// from where it stands when the bond breaks (`contact_under_bond`);
    /// otherwise it is held at zero under the bond and starts afresh.
    pub fn contact_goes_on_under_bond(&self) -> bool {
        BondParams::switch(self.params.contact_under_bond)
    }

    /// Whether a wall bond follows LIGGGHTS-INL's geometry (`bond::wall`):
    /// under its code (`inl_compatible`) and its linear bond.
    pub fn inl_wall(&self) -> bool {
        self.inl || self.linear
    }

    /// The largest centre distance an intact bond of rest length `r0` can
    /// reach: engines must keep pairs this far apart in their neighbour
    /// lists. Distance mode: `max_distance`. Stress mode: the stretch at which
    /// the tensile stress of the virgin tension line alone reaches its limit
    /// (`gamma sigma_max / k_fn2`); infinite when that never happens.
    pub fn max_bond_distance(&self, r0: f64) -> f64 {
        if self.stress_break {
            let k = if self.linear {
                self.params.k_n
            } else {
                self.params.k_fn2
            };
            if k > 0.0 && (self.features & TENSION) != 0 {
                r0 + self.limits.max_sigma * self.limits.tension_factor / k
            } else {
                f64::INFINITY
            }
        } else {
            self.params.max_distance
        }
    }

    /// Neighbour-list reach an engine needs so no intact bond drops out of
    /// its lists, as a multiple of the contact distance `2 min_radius` of the
    /// smallest spheres, with a 10% margin: the largest bonded centre distance
    /// is `max_distance` (distance mode) or the creation distance plus the
    /// largest tensile stretch (stress mode). Infinite when a bond can stretch
    /// without limit (distance mode with `max_distance = inf`, or stress mode
    /// with tension switched off or an infinite strength).
    pub fn contact_distance_factor(&self, min_radius: f64) -> f64 {
        let reach = if self.stress_break {
            self.max_bond_distance(self.params.create_distance)
        } else {
            self.params.max_distance
        };
        (1.1 * reach / (2.0 * min_radius)).max(1.0)
    }
}
