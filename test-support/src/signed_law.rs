//! The signed two-sided hysteresis law of one angle, written from the
//! table of docs/models/bond-nonlinear.md independently of the core: the
//! reference the torque tests compare the core's twisting and bending with.

/// Branch of the three-branch loop `h(x; x_max)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Branch {
    Virgin,
    Unloading,
    Reverse,
}

/// `h(x; x_max)` of the law's table, and which branch gave it.
pub fn loop_value(k: f64, ku: f64, kc: f64, x: f64, x_max: f64) -> (f64, Branch) {
    let c = (ku - k) / (ku + kc);
    if x >= x_max {
        (k * x, Branch::Virgin)
    } else if x >= c * x_max {
        (ku * x + (k - ku) * x_max, Branch::Unloading)
    } else {
        (-kc * x, Branch::Reverse)
    }
}

/// The signed two-sided law of one angle `s`, history updated before the
/// law (`reset`: the other side's extreme is forgotten while on one side).
#[derive(Default)]
pub struct SignedLaw {
    pub max: f64,
    pub min: f64,
}

impl SignedLaw {
    pub fn value(&mut self, (k, ku, kc): (f64, f64, f64), s: f64, reset: bool) -> (f64, Branch, bool) {
        if reset {
            if s > 0.0 {
                self.min = 0.0;
            }
            if s < 0.0 {
                self.max = 0.0;
            }
        }
        self.max = self.max.max(s);
        self.min = self.min.min(s);
        if s >= 0.0 {
            let (h, b) = loop_value(k, ku, kc, s, self.max);
            (h, b, true)
        } else {
            let (h, b) = loop_value(k, ku, kc, -s, -self.min);
            (-h, b, false)
        }
    }
}
