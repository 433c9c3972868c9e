//! The time-step check engines run at every `run` and again when the atom
//! count changes: over every pair of atom types present, the bond or
//! contact with the shortest critical step between the smallest and
//! lightest spheres of the two types.

use crate::bond::timestep::{ModeLimits, RATTLE_MARGIN};
use crate::stability::RECOMMENDED_FRACTION;

/// The extremes of one atom type over the whole simulation (all ranks).
/// A type with no atom has infinite `radius_min` and `mass_min`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TypeBodies {
    /// The smallest radius.
    pub radius_min: f64,
    /// The largest radius.
    pub radius_max: f64,
    /// The smallest mass.
    pub mass_min: f64,
}

impl TypeBodies {
    /// No atom of the type (the start of a min/max reduction).
    pub fn none() -> TypeBodies {
        TypeBodies {
            radius_min: f64::INFINITY,
            radius_max: 0.0,
            mass_min: f64::INFINITY,
        }
    }

    /// Whether atoms of the type exist (finite, positive extremes).
    pub fn present(&self) -> bool {
        let positive = |x: f64| x.is_finite() && x > 0.0;
        positive(self.radius_min) && positive(self.mass_min) && self.radius_max >= self.radius_min
    }
}

/// Names of the deck's units in messages. The estimates are ratios of
/// masses, stiffnesses and lengths, so they hold in any consistent unit
/// system; only the names change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnitNames {
    /// Unit of length.
    pub length: &'static str,
    /// Unit of mass.
    pub mass: &'static str,
    /// Unit of time.
    pub time: &'static str,
    /// Unit of stress.
    pub stress: &'static str,
}

impl UnitNames {
    /// The SI names: m, kg, s, Pa.
    pub const SI: UnitNames = UnitNames {
        length: "m",
        mass: "kg",
        time: "s",
        stress: "Pa",
    };

    /// The names of an engine's `units` style; the styles granular decks
    /// use are named, any other is said as "(units STYLE)".
    pub fn of_style(style: &str) -> UnitNames {
        match style {
            "si" => Self::SI,
            "cgs" => UnitNames {
                length: "cm",
                mass: "g",
                time: "s",
                stress: "dyne/cm^2",
            },
            "micro" => UnitNames {
                length: "um",
                mass: "pg",
                time: "us",
                stress: "pg/(um us^2)",
            },
            "nano" => UnitNames {
                length: "nm",
                mass: "ag",
                time: "ns",
                stress: "ag/(nm ns^2)",
            },
            _ => UnitNames {
                length: "(length, deck units)",
                mass: "(mass, deck units)",
                time: "(time, deck units)",
                stress: "(stress, deck units)",
            },
        }
    }
}

/// How the time step compares with the estimate.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum TimestepLevel {
    /// At or below the recommended step (or nothing to check).
    Safe = 0,
    /// Above the recommended step, at or below the critical one.
    AboveRecommended = 1,
    /// Above the critical step: explicit integration is unstable.
    AboveCritical = 2,
}

/// The square root's rattle against the compression break threshold, for
/// the message ([`crate::bond::BondModel::rattle_timestep`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rattle {
    /// `(max_sigma / k_fn1)^2`.
    pub threshold: f64,
    /// `compression_noise_floor` at the deck's step.
    pub floor: f64,
    /// The longest step that keeps the floor `RATTLE_MARGIN` below the
    /// threshold.
    pub step: f64,
    /// The bond type's `max_sigma`.
    pub max_sigma: f64,
    /// The bond type's `k_fn1`.
    pub k_fn1: f64,
    /// Bond radius (the regularisation suggested is a fraction of it).
    pub rb: f64,
}

/// Bonds at rest under the plain square root, for the message
/// ([`crate::bond::BondModel::rest_timestep`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AtRest {
    /// The longest step at which they gain no energy (0: none).
    pub step: f64,
    /// That step as a fraction of the recommended one.
    pub fraction: f64,
    /// The recommended step by the other rules (the critical step's
    /// fraction, the rattle).
    pub recommended: f64,
    /// The bond type's `ku_fn1 / k_fn1`.
    pub ratio: f64,
    /// The bond type's percentage damping of the normal force, as counted.
    pub eta_fn: f64,
    /// The regularisation suggested
    /// ([`crate::bond::BondModel::rest_regularisation`]).
    pub regularisation: f64,
    /// Whether it matches the tension slope at rest (else `1e-3 rb`).
    pub matched: bool,
    /// The recommended step of the same bonds so regularised.
    pub regularised: f64,
}

/// The estimates of one type pair at the deck's step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepLimits {
    /// One bond or contact between two spheres.
    pub critical: f64,
    /// The step to use; the warning threshold.
    pub recommended: f64,
    /// The bond's modes (for the limits of coordinated spheres); `None` for
    /// contacts.
    pub modes: Option<ModeLimits>,
    /// Where bonds can break in compression from the rattle.
    pub rattle: Option<Rattle>,
    /// Where bonds at rest gain energy below the recommended step.
    pub at_rest: Option<AtRest>,
}

impl StepLimits {
    /// A limit with nothing but its critical step.
    pub fn plain(critical: f64) -> StepLimits {
        StepLimits {
            critical,
            recommended: RECOMMENDED_FRACTION * critical,
            modes: None,
            rattle: None,
            at_rest: None,
        }
    }
}

/// The type pair that limits the step, and how `dt` compares with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimestepVerdict {
    /// How `dt` compares with the pair's steps.
    pub level: TimestepLevel,
    /// The first atom type of the pair (`type_a <= type_b`).
    pub type_a: usize,
    /// The second atom type of the pair.
    pub type_b: usize,
    /// The pair's critical step.
    pub critical: f64,
    /// The pair's recommended step.
    pub recommended: f64,
    /// The time step judged.
    pub dt: f64,
    /// The pair's estimates.
    pub limits: StepLimits,
}

/// The limiting pair (shortest recommended step) over types `1..=ntypes`
/// (`bodies[t]`, index 0 unused) with a model (`model(a, b)`, `a <= b`), and
/// the verdict on `dt`. `limits(model, r_a, r_b, m_a, m_b)` gives the
/// pair's estimates. `None` when no pair of present types has a model, or
/// every estimate is infinite (no stiffness). A critical step that is not a
/// positive number (radii or masses outside what it can evaluate) is `Err`
/// with the pair.
pub fn scan<M>(
    ntypes: usize,
    bodies: &[TypeBodies],
    model: impl Fn(usize, usize) -> Option<M>,
    limits: impl Fn(&M, f64, f64, f64, f64) -> StepLimits,
    dt: f64,
) -> Result<Option<TimestepVerdict>, (usize, usize, f64)> {
    let mut worst: Option<TimestepVerdict> = None;
    for a in 1..=ntypes {
        for b in a..=ntypes {
            let (ba, bb) = (bodies[a], bodies[b]);
            if !(ba.present() && bb.present()) {
                continue;
            }
            let Some(m) = model(a, b) else { continue };
            let l = limits(&m, ba.radius_min, bb.radius_min, ba.mass_min, bb.mass_min);
            let c = l.critical;
            if !(c > 0.0) {
                return Err((a, b, c));
            }
            if l.recommended.is_finite() && worst.is_none_or(|w| l.recommended < w.recommended) {
                worst = Some(TimestepVerdict {
                    level: TimestepLevel::Safe,
                    type_a: a,
                    type_b: b,
                    critical: c,
                    recommended: l.recommended,
                    dt,
                    limits: l,
                });
            }
        }
    }
    Ok(worst.map(|mut w| {
        w.level = if dt > w.critical {
            TimestepLevel::AboveCritical
        } else if dt > w.recommended {
            TimestepLevel::AboveRecommended
        } else {
            TimestepLevel::Safe
        };
        w
    }))
}

/// How a message names the parameters it cites.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CitedNames {
    /// The deck's name of `max_sigma`.
    pub max_sigma: &'static str,
    /// The deck's name of `k_fn1`.
    pub k_fn1: &'static str,
    /// The deck's name of `compression_linear_below`.
    pub compression_linear_below: &'static str,
    /// The deck's name of `ku_fn1`.
    pub ku_fn1: &'static str,
    /// The deck's name of `k_fn2`.
    pub k_fn2: &'static str,
    /// The deck's name of `eta_fn`.
    pub eta_fn: &'static str,
    /// The deck's name of `k_ft`.
    pub k_ft: &'static str,
    /// The deck's name of `k_tn`.
    pub k_tn: &'static str,
    /// The deck's name of `k_tt`.
    pub k_tt: &'static str,
}

impl TimestepVerdict {
    /// The warning an engine prints (empty when safe). `style` names the
    /// deck command, `what` the interaction ("bond", "contact"), `names`
    /// the parameters as the deck spells them, `units` the deck's units.
    pub fn message(
        &self,
        style: &str,
        what: &str,
        bodies: &[TypeBodies],
        names: &CitedNames,
        units: &UnitNames,
    ) -> String {
        let (a, b) = (self.type_a, self.type_b);
        let (verb, limit_name, limit) = match self.level {
            TimestepLevel::Safe => return String::new(),
            TimestepLevel::AboveRecommended => ("exceeds", "recommended", self.recommended),
            TimestepLevel::AboveCritical => ("EXCEEDS", "critical", self.critical),
        };
        let UnitNames {
            length: l,
            mass: kg,
            time: s,
            stress: pa,
        } = *units;
        // Where no step is stable (bonds at rest under the plain square
        // root, elastic and undamped) there is no step to exceed.
        let compared = if limit > 0.0 {
            format!("{verb} the {limit_name} step {} {s} of", short(limit))
        } else {
            "is not stable for".to_string()
        };
        let mut text = format!(
            "{style}: time step {dt} {s} {compared} the stiffest {what} \
             (atom types {a} and {b}, smallest radius {ra} / {rb} {l}, lightest mass {ma} / {mb} {kg}; \
             critical step {c} {s}",
            dt = short(self.dt),
            ra = short(bodies[a].radius_min),
            rb = short(bodies[b].radius_min),
            ma = short(bodies[a].mass_min),
            mb = short(bodies[b].mass_min),
            c = short(self.critical),
        );
        match self.limits.modes {
            Some(modes) => {
                let covered = match modes.bonds_covered(self.dt) {
                    0 => "for no sphere".to_string(),
                    u32::MAX => "for any z".to_string(),
                    z => format!("for z <= {z}"),
                };
                text += &format!(
                    ", the limit of one {what} between two free spheres; a sphere with z {what}s is stable below \
                     {z6} {s} for z = 6, {z12} {s} for z = 12, this time step {covered})",
                    z6 = short(modes.coordinated(6)),
                    z12 = short(modes.coordinated(12)),
                )
            }
            None => text += ")",
        }
        // the deck's words that set the step: the stiffness of the mode
        // that limits it, and the time step itself
        if let Some(m) = self.limits.modes {
            let modes = [
                (m.axial, "axial", format!("{} and {}", names.k_fn2, names.k_fn1)),
                (m.shear, "shear", names.k_ft.to_string()),
                (m.twist, "twisting", names.k_tn.to_string()),
                (m.bend, "bending", names.k_tt.to_string()),
            ];
            if let Some((_, mode, words)) = modes
                .iter()
                .filter(|(t, _, _)| t.is_finite())
                .min_by(|a, b| a.0.total_cmp(&b.0))
            {
                text +=
                    &format!("; the {mode} mode sets it ({words}): a smaller timestep or a softer {words}");
            }
        }
        if let Some(r) = self.limits.rattle.filter(|r| self.dt > r.step) {
            text += &format!(
                ". Bonds near zero compression can break in compression from round-off: at this step the \
                 square root's rattle reaches {floor} {l} (the noise floor), not {margin} times below the \
                 compression break threshold ({ms} / {k})^2 = {th} {l} ({ms} = {sig} {pa}, {k} = {kf}). \
                 Remedies: timestep <= {step} {s}, or the linear regularisation {clb} (for example 1e-3 of \
                 the bond radius, {eps} {l}), which removes the rattle",
                floor = short(r.floor),
                margin = RATTLE_MARGIN,
                ms = names.max_sigma,
                k = names.k_fn1,
                th = short(r.threshold),
                sig = short(r.max_sigma),
                kf = short(r.k_fn1),
                step = short(r.step),
                clb = names.compression_linear_below,
                eps = short(1e-3 * r.rb),
            );
        }
        let at_rest = self.limits.at_rest.filter(|r| self.dt > r.step);
        if let Some(r) = at_rest {
            let measured = format!(
                "{k}/{k1} = {ratio}, {eta} = {e}",
                k = names.ku_fn1,
                k1 = names.k_fn1,
                ratio = plain(r.ratio),
                eta = names.eta_fn,
                e = plain(r.eta_fn),
            );
            let recommended = short(r.recommended);
            let gain = if r.step > 0.0 {
                format!(
                    "gain energy above {f} of the recommended step {recommended} {s}, at {step} {s} \
                     (measured for {measured})",
                    f = r.fraction,
                    step = short(r.step),
                )
            } else {
                format!(
                    "gain energy at every time step measured, down to 0.05 of the recommended step \
                     {recommended} {s} ({measured}): this law cannot be integrated stably at rest"
                )
            };
            let why = if r.matched {
                format!(
                    "({k1}/{k2})^2, where the compression slope at rest equals the tension slope",
                    k1 = names.k_fn1,
                    k2 = names.k_fn2
                )
            } else {
                "1e-3 of the bond radius".to_string()
            };
            text += &format!(
                ". Bonds rest at zero compression, where the plain square root's stiffness is unbounded \
                 ({clb} not set); there they {gain}. Remedy: the linear regularisation {clb} {eps} {l} \
                 ({why}; recommended step then {reg} {s}), or more hysteresis ({k}) or damping ({eta})",
                clb = names.compression_linear_below,
                eps = short(r.regularisation),
                reg = short(r.regularised),
                k = names.ku_fn1,
                eta = names.eta_fn,
            );
        }
        if self.recommended > 0.0 {
            let rule = if at_rest.is_some_and(|r| r.step <= self.recommended) {
                "set by the bonds at rest".to_string()
            } else if self.limits.recommended < RECOMMENDED_FRACTION * self.critical {
                "set by the rattle".to_string()
            } else {
                format!("{RECOMMENDED_FRACTION} of the critical")
            };
            text += &format!(
                ". Use timestep <= {r} {s} (the core's recommended step, {rule})",
                r = short(self.recommended)
            );
        }
        text
    }
}

/// A ratio or fraction in messages: four significant digits, written out
/// (`1.1`, `0.001`, `0`).
pub fn plain(x: f64) -> String {
    short(x)
        .parse::<f64>()
        .map_or_else(|_| short(x), |v| v.to_string())
}

/// A number in messages: four significant digits, trailing zeros dropped
/// (`4.034e-8`, `1e-3`).
pub fn short(x: f64) -> String {
    let text = format!("{x:.3e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) if mantissa.contains('.') => {
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            format!("{mantissa}e{exponent}")
        }
        _ => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(r: f64, m: f64) -> TypeBodies {
        TypeBodies {
            radius_min: r,
            radius_max: r,
            mass_min: m,
        }
    }

    // critical step of a fake model k: 2 sqrt(m_eff / k)
    fn spring(k: &f64, _: f64, _: f64, mi: f64, mj: f64) -> StepLimits {
        StepLimits::plain(2.0 * (mi * mj / (mi + mj) / k).sqrt())
    }

    const NAMES: CitedNames = CitedNames {
        max_sigma: "max_sigma",
        k_fn1: "k_fn1",
        compression_linear_below: "compression_linear_below",
        ku_fn1: "ku_fn1",
        k_fn2: "k_fn2",
        eta_fn: "eta_fn",
        k_ft: "k_ft",
        k_tn: "k_tn",
        k_tt: "k_tt",
    };

    #[test]
    fn the_lightest_stiffest_pair_limits_and_absent_types_are_skipped() {
        let bodies = [
            TypeBodies::none(),
            sphere(1e-3, 1e-5),
            sphere(1e-3, 4e-5),
            TypeBodies::none(),
        ];
        let stiffness = |a: usize, b: usize| Some(if a == b { 1e4 } else { 1e6 });
        let v = scan(3, &bodies, stiffness, spring, 1e-9).unwrap().unwrap();
        assert_eq!((v.type_a, v.type_b), (1, 2));
        assert_eq!(v.critical, spring(&1e6, 0.0, 0.0, 1e-5, 4e-5).critical);
        assert_eq!(v.level, TimestepLevel::Safe);
        assert!(v.message("s", "bond", &bodies, &NAMES, &UnitNames::SI).is_empty());
    }

    #[test]
    fn a_bond_warning_names_the_stiffness_of_the_mode_that_limits_the_step() {
        let bodies = [TypeBodies::none(), sphere(1e-3, 1e-5)];
        let modes = |shear: f64| ModeLimits {
            axial: 2e-6,
            shear,
            twist: 5e-6,
            bend: 4e-6,
        };
        for (shear, mode, words) in [(1e-6, "shear", "(k_ft)"), (3e-6, "axial", "(k_fn2 and k_fn1)")] {
            let verdict = TimestepVerdict {
                level: TimestepLevel::AboveRecommended,
                type_a: 1,
                type_b: 1,
                critical: 1e-6,
                recommended: 2e-7,
                dt: 5e-7,
                limits: StepLimits {
                    modes: Some(modes(shear)),
                    ..StepLimits::plain(1e-6)
                },
            };
            let text = verdict.message(
                "pair granbond",
                "bond",
                &bodies,
                &NAMES,
                &UnitNames::of_style("si"),
            );
            assert!(
                text.contains(&format!("the {mode} mode sets it {words}")),
                "{text}"
            );
        }
    }

    #[test]
    fn levels_follow_the_two_limits() {
        let bodies = [TypeBodies::none(), sphere(1e-3, 1e-5)];
        let c = spring(&1e4, 0.0, 0.0, 1e-5, 1e-5).critical;
        let level = |dt: f64| {
            scan(1, &bodies, |_, _| Some(1e4), spring, dt)
                .unwrap()
                .unwrap()
                .level
        };
        assert_eq!(level(RECOMMENDED_FRACTION * c), TimestepLevel::Safe);
        assert_eq!(level(0.5 * c), TimestepLevel::AboveRecommended);
        assert_eq!(level(1.01 * c), TimestepLevel::AboveCritical);
        let v = scan(1, &bodies, |_, _| Some(1e4), spring, 1.01 * c)
            .unwrap()
            .unwrap();
        let msg = v.message("pair granbond", "contact", &bodies, &NAMES, &UnitNames::SI);
        assert!(
            msg.starts_with("pair granbond: time step") && msg.contains("EXCEEDS the critical step"),
            "{msg}"
        );
    }

    #[test]
    fn nothing_to_check_and_bad_estimates() {
        let bodies = [TypeBodies::none(), TypeBodies::none()];
        assert_eq!(scan(1, &bodies, |_, _| Some(1.0), spring, 1.0), Ok(None));
        let bodies = [TypeBodies::none(), sphere(1e-3, 1e-5)];
        assert_eq!(scan(1, &bodies, |_, _| None::<f64>, spring, 1.0), Ok(None));
        assert_eq!(scan(1, &bodies, |_, _| Some(0.0), spring, 1.0), Ok(None)); // no stiffness: infinite
        let nan = |_: &f64, _: f64, _: f64, _: f64, _: f64| StepLimits::plain(f64::NAN);
        assert!(scan(1, &bodies, |_, _| Some(1.0), nan, 1.0).is_err());
    }
}
