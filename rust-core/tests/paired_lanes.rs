//! The kernel pairs independent square roots and divisions (the bending
//! angle with its history extreme, ...) into two-lane instructions, and selects hysteresis branches
//! without jumps. Both must give exactly, bit for bit, what the plain scalar
//! formulas give.

use granbond_test_support as common;

use granbond::bond::damping::{reciprocal_unit, unit_scale};
use granbond::bond::features::{BEND, TWIST};
use granbond::bond::hysteresis::Loop;
use granbond::bond::paired::{norms, reciprocals};
use granbond::bond::twist_bend::{BendHistory, TorqueLaw, TwistHistory};
use granbond::bond::{BondModel, BondOutput, BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond::real::paired::{div2, sqrt2};
use granbond::vector::{tangential_part, Vec3};

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Mostly random magnitudes over many decades, sometimes exact zeros.
    fn value(&mut self) -> f64 {
        let u = self.next();
        if u < 0.05 {
            0.0
        } else {
            (2.0 * self.next() - 1.0) * 10f64.powf(-12.0 + 16.0 * self.next())
        }
    }

    fn vec(&mut self) -> Vec3 {
        Vec3::new(self.value(), self.value(), self.value())
    }
}

fn same(a: Vec3, b: Vec3) -> bool {
    a.iter().zip(b.iter()).all(|(x, y)| x.to_bits() == y.to_bits())
}

#[test]
fn two_lane_roots_and_quotients_are_the_scalar_ones() {
    let mut rng = Rng(1);
    for _ in 0..20_000 {
        let (a, b, c, d) = (rng.value().abs(), rng.value().abs(), rng.value(), rng.value());
        let (r, s) = sqrt2(a, b);
        assert_eq!(
            (r.to_bits(), s.to_bits()),
            (a.sqrt().to_bits(), b.sqrt().to_bits())
        );
        let (q, t) = div2(a, c, b, d);
        assert_eq!((q.to_bits(), t.to_bits()), ((a / c).to_bits(), (b / d).to_bits()));
        let (u, v) = (rng.vec(), rng.vec());
        let (nu, nv) = norms(u, true, v, true);
        assert_eq!(
            (nu.to_bits(), nv.to_bits()),
            (u.norm().to_bits(), v.norm().to_bits())
        );
    }
}

#[test]
fn torque_magnitudes_from_the_laws_are_the_norms_of_the_torques() {
    // |h| * moment replaces the norm of the torque (no square root) in the
    // stresses and the damping: equal up to a few roundings.
    let mut rng = Rng(2);
    for history_reset in [false, true] {
        let twist = TorqueLaw {
            hysteresis: Loop::new(5e12, 1.5e13, 5e11),
            history_reset,
        };
        let bend = TorqueLaw {
            hysteresis: Loop::new(4e12, 8e12, 1e12),
            history_reset,
        };
        for _ in 0..20_000 {
            let n = rng.vec();
            if !(n.norm() > 0.0 && n.norm().is_finite()) {
                continue;
            }
            let n = n * (1.0 / n.norm());
            let (ta, tb) = (n * rng.value(), tangential_part(rng.vec(), n));
            let moment = rng.value().abs();
            let (a, _) = twist.twist(
                ta,
                n,
                TwistHistory {
                    max: rng.value().abs(),
                    min: -rng.value().abs(),
                },
                moment,
            );
            let (b, _) = bend.bend(
                tb,
                n,
                BendHistory {
                    leading: rng.vec(),
                    opposite: rng.value().abs(),
                },
                moment,
            );
            for t in [a, b] {
                let norm = t.torque.norm();
                if norm.is_finite() {
                    assert!(
                        (norm - t.magnitude).abs() <= 1e-14 * norm.max(t.magnitude),
                        "{norm} vs {}",
                        t.magnitude
                    );
                }
            }
        }
    }
}

#[test]
fn paired_unit_vectors_are_the_plain_quotients() {
    let mut rng = Rng(3);
    for smooth in [false, true] {
        for _ in 0..20_000 {
            let (a, b) = (rng.vec(), rng.vec());
            let eps = 1e-3;
            let plain = |v: Vec3| {
                let len = v.norm();
                let scale = if smooth { len.max(eps) } else { len };
                // The kernel's formula: one reciprocal, three products.
                if scale > 0.0 {
                    v * (1.0 / scale)
                } else {
                    Vec3::zeros()
                }
            };
            // The kernel's path: the divisors, their reciprocals paired
            // (or one alone), the products.
            let (sa, sb) = (
                unit_scale(a.norm(), eps, smooth),
                unit_scale(b.norm(), eps, smooth),
            );
            let (ia, _) = reciprocals(sa, true, sb, false);
            assert!(same(reciprocal_unit(a, sa, ia), plain(a)));
            let (ia, ib) = reciprocals(sa, true, sb, true);
            let (ua, ub) = (reciprocal_unit(a, sa, ia), reciprocal_unit(b, sb, ib));
            assert!(same(ua, plain(a)) && same(ub, plain(b)));
        }
    }
}

#[test]
fn hysteresis_branches_without_jumps_are_the_spec_branches() {
    let mut rng = Rng(4);
    for law in [
        Loop::new(1e10, 3e10, 1e9),
        Loop::new(1e10, 1e10, 0.0),
        Loop::new(0.0, 0.0, 0.0),
    ] {
        for _ in 0..20_000 {
            let x_max = rng.value().abs();
            let x = x_max * rng.next();
            let expected = if x >= x_max {
                law.k * x
            } else if x >= law.c * x_max {
                law.ku * x + (law.k - law.ku) * x_max
            } else {
                -law.kc * x
            };
            assert_eq!(law.value(x, x_max).to_bits(), expected.to_bits());
        }
    }
}

/// In the full kernel twisting and bending share instructions; with only one
/// of them on, each runs alone. The angles, history maxima and shear state
/// (which do not depend on the other law) must come out identical.
#[test]
fn paired_twist_and_bend_states_match_each_alone() {
    let params = BondParams {
        damping: 1,
        eta_fn: 0.1,
        eta_ft: 0.1,
        eta_tn: 0.1,
        eta_tt: 0.1,
        ..common::params()
    };
    let both = BondModel::new(params).unwrap();
    let twist_only = BondModel::new(BondParams { bend: 0, ..params }).unwrap();
    let bend_only = BondModel::new(BondParams { twist: 0, ..params }).unwrap();
    assert_eq!(both.features & (TWIST | BEND), TWIST | BEND);
    let mut rng = Rng(5);
    let r0 = 2e-3;
    let (mut s2, mut st, mut sb) = (
        BondState::created(r0),
        BondState::created(r0),
        BondState::created(r0),
    );
    let mut out = BondOutput::default();
    for _ in 0..2_000 {
        let w = |rng: &mut Rng| {
            [
                4.0 * rng.next() - 2.0,
                4.0 * rng.next() - 2.0,
                4.0 * rng.next() - 2.0,
            ]
        };
        let kin = PairKinematics {
            x_i: [
                r0 * (1.0 + 1e-3 * (2.0 * rng.next() - 1.0)),
                1e-5 * rng.next(),
                0.0,
            ],
            v_i: [0.01 * rng.next(), -0.01 * rng.next(), 0.0],
            w_i: w(&mut rng),
            w_j: w(&mut rng),
            radius_i: 1e-3,
            radius_j: 1e-3,
            ..PairKinematics::default()
        };
        both.step(&kin, 1e-6, &mut s2, &mut out).unwrap();
        twist_only.step(&kin, 1e-6, &mut st, &mut out).unwrap();
        bend_only.step(&kin, 1e-6, &mut sb, &mut out).unwrap();
        assert_eq!(s2.twist_angle.map(f64::to_bits), st.twist_angle.map(f64::to_bits));
        assert_eq!(s2.twist_max.to_bits(), st.twist_max.to_bits());
        assert_eq!(s2.twist_min.to_bits(), st.twist_min.to_bits());
        assert_eq!(s2.bend_angle.map(f64::to_bits), sb.bend_angle.map(f64::to_bits));
        assert_eq!(
            s2.bend_history.map(f64::to_bits),
            sb.bend_history.map(f64::to_bits)
        );
        assert_eq!(s2.bend_opposite.to_bits(), sb.bend_opposite.to_bits());
        assert_eq!(s2.shear_force.map(f64::to_bits), st.shear_force.map(f64::to_bits));
    }
}
