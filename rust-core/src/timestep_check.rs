//! The time-step check engines run at every `run` and again when the atom
//! count changes: over every pair of atom types present, the bond or
//! contact with the shortest critical step between the smallest and
//! lightest spheres of the two types.

use crate::stability::RECOMMENDED_FRACTION;

/// The extremes of one atom type over the whole simulation (all ranks).
/// A type with no atom has infinite `radius_min` and `mass_min`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TypeBodies {
    pub radius_min: f64,
    pub radius_max: f64,
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

/// The type pair that limits the step, and how `dt` compares with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimestepVerdict {
    pub level: TimestepLevel,
    pub type_a: usize,
    pub type_b: usize,
    pub critical: f64,
    pub recommended: f64,
    pub dt: f64,
}

/// The limiting pair over types `1..=ntypes` (`bodies[t]`, index 0 unused)
/// with a model (`model(a, b)`, `a <= b`), and the verdict on `dt`. `None`
/// when no pair of present types has a model, or every estimate is
/// infinite (no stiffness). An estimate that is not a positive number (radii
/// or masses outside what it can evaluate) is `Err` with the pair.
pub fn scan<M>(
    ntypes: usize,
    bodies: &[TypeBodies],
    model: impl Fn(usize, usize) -> Option<M>,
    critical: impl Fn(&M, f64, f64, f64, f64) -> f64,
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
            let c = critical(&m, ba.radius_min, bb.radius_min, ba.mass_min, bb.mass_min);
            if !(c > 0.0) {
                return Err((a, b, c));
            }
            if c.is_finite() && worst.map_or(true, |w| c < w.critical) {
                worst = Some(TimestepVerdict {
                    level: TimestepLevel::Safe,
                    type_a: a,
                    type_b: b,
                    critical: c,
                    recommended: RECOMMENDED_FRACTION * c,
                    dt,
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

impl TimestepVerdict {
    /// The warning an engine prints (empty when safe). `style` names the
    /// deck command, `what` the interaction ("bond", "contact").
    pub fn message(&self, style: &str, what: &str, bodies: &[TypeBodies]) -> String {
        let (a, b) = (self.type_a, self.type_b);
        let (verb, limit_name, limit) = match self.level {
            TimestepLevel::Safe => return String::new(),
            TimestepLevel::AboveRecommended => ("exceeds", "recommended", self.recommended),
            TimestepLevel::AboveCritical => ("EXCEEDS", "critical", self.critical),
        };
        format!(
            "{style}: time step {dt:e} s {verb} the {limit_name} step {limit:e} s of the stiffest {what} \
             (atom types {a} and {b}, smallest radius {ra:e} / {rb:e} m, lightest mass {ma:e} / {mb:e} kg; \
             critical step {c:e} s). Use timestep <= {r:e} s (the core's recommended step, {f} of the critical)",
            dt = self.dt,
            ra = bodies[a].radius_min,
            rb = bodies[b].radius_min,
            ma = bodies[a].mass_min,
            mb = bodies[b].mass_min,
            c = self.critical,
            r = self.recommended,
            f = RECOMMENDED_FRACTION,
        )
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
    fn spring(k: &f64, _: f64, _: f64, mi: f64, mj: f64) -> f64 {
        2.0 * (mi * mj / (mi + mj) / k).sqrt()
    }

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
        assert_eq!(v.critical, spring(&1e6, 0.0, 0.0, 1e-5, 4e-5));
        assert_eq!(v.level, TimestepLevel::Safe);
        assert!(v.message("s", "bond", &bodies).is_empty());
    }

    #[test]
    fn levels_follow_the_two_limits() {
        let bodies = [TypeBodies::none(), sphere(1e-3, 1e-5)];
        let c = spring(&1e4, 0.0, 0.0, 1e-5, 1e-5);
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
        let msg = v.message("pair granbond", "contact", &bodies);
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
        let nan = |_: &f64, _: f64, _: f64, _: f64, _: f64| f64::NAN;
        assert!(scan(1, &bodies, |_, _| Some(1.0), nan, 1.0).is_err());
    }
}
