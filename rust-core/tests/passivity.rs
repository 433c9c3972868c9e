//! No bond law does work of its own (docs/models/bond-nonlinear.md,
//! "Energy"): over any closed path of its deformation at a fixed history
//! the bond does no positive work on what drives it; its loads are the
//! gradient of the energy it stores (`BondModel::stored_energy`); a path
//! that moves the history dissipates. Bending in one plane is the signed
//! two-sided law (the reference in test-support, from the law's table).
//!
//! The bond is driven as an engine would drive it: sphere `j` held at the
//! origin, sphere `i` turned (or moved along the axis) at a constant rate
//! on each straight leg of the path, one step at a time; the work on the
//! driver is the trapezoid sum of load times displacement.

use granbond_test_support as common;

use common::signed_law::SignedLaw;
use common::strategies::{stiffness_loop, vec3};
use common::*;
use granbond::bond::section::section;
use granbond::bond::{BondModel, BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond::vector::{v3, Vec3};
use proptest::prelude::*;

const DT: f64 = 1e-6;
/// Steps per straight leg of a path.
const STEPS: usize = 500;
/// Round-off, as a fraction of the gross work.
const ROUND_OFF: f64 = 1e-12;
const R0: f64 = 2.0 * RADIUS;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Dof {
    Normal,
    Twist,
    Bend,
}

/// A bond with only `dof` switched on (no damping), its loop of that part
/// from `(k, ku, kc)`; the normal law gets it on both sides, continued
/// linearly below `eps` in compression.
fn only(dof: Dof, (k, ku, kc): (f64, f64, f64), eps: f64, history_reset: bool) -> BondModel {
    let p = BondParams {
        tension: (dof == Dof::Normal) as i32,
        compression: (dof == Dof::Normal) as i32,
        shear: 0,
        twist: (dof == Dof::Twist) as i32,
        bend: (dof == Dof::Bend) as i32,
        history_reset: history_reset as i32,
        compression_linear_below: eps,
        ..params()
    };
    model(match dof {
        // compression stiffness per sqrt(m): k_fn1 ~ k_fn2 * sqrt(1e-6 m)
        Dof::Normal => BondParams {
            k_fn1: k * 1e-3,
            ku_fn1: ku * 1e-3,
            kc_fn1: kc * 1e-3,
            k_fn2: k,
            ku_fn2: ku,
            kc_fn2: kc,
            ..p
        },
        Dof::Twist => BondParams {
            k_tn: k,
            ku_tn: ku,
            kc_tn: kc,
            ..p
        },
        Dof::Bend => BondParams {
            k_tt: k,
            ku_tt: ku,
            kc_tt: kc,
            ..p
        },
    })
}

/// The unit axis of a random vector (x when it is too short).
fn axis(d: [f64; 3]) -> Vec3 {
    let d = v3(d);
    if d.norm() < 1e-3 {
        v3([1.0, 0.0, 0.0])
    } else {
        d * (1.0 / d.norm())
    }
}

/// A unit vector across `n`.
fn across(n: Vec3) -> Vec3 {
    let t = if n.x.abs() < 0.9 {
        v3([1.0, 0.0, 0.0])
    } else {
        v3([0.0, 1.0, 0.0])
    };
    let t = t - n * t.dot(&n);
    t * (1.0 / t.norm())
}

/// A bond along `n` driven along a path of its deformation: the bending
/// angle, the twisting angle (along `n`) or the compression `delta`
/// (along `n` too, as `delta n`), with the work it does on the driver.
#[derive(Clone)]
struct Drive {
    m: BondModel,
    dof: Dof,
    n: Vec3,
    state: BondState,
    /// The deformation now (a vector; `delta n` for the normal law).
    at: Vec3,
    /// The load on the driven coordinate at `at`: the torque on `i`, or
    /// minus the force on `i` (the driver pushes `delta` up by moving `i`
    /// towards `j`).
    load: Vec3,
    /// Work of the bond on the driver.
    work: f64,
    /// Sum of |load| |displacement|.
    gross: f64,
    /// A bound of the trapezoid sum's error: where two branches meet (a
    /// kink of slope change `s` at `a` in a step of length `h`) the sum is
    /// off by `s a (h - a) / 2 <= s h^2 / 8`, and the second differences
    /// of `load . step` around that step add up to at least `s h^2`; on a
    /// smooth stretch the error is `h^3 f''/12`, the second difference
    /// `h^3 f''`. So a quarter of the sum of the second differences bounds
    /// it, also where the square root's slope is unbounded (at zero) or a
    /// history update changes the law. The argument needs each step inside
    /// two windows of three loads, so each leg's windows reach one step
    /// past its ends (loads taken on a copy of the bond).
    quadrature: f64,
    /// Steps per leg.
    steps: usize,
}

impl Drive {
    /// The bond at deformation `at` with `state`'s history; one step that
    /// does not move it gives the load there (the history is updated for
    /// it, as any step does).
    fn new(m: BondModel, dof: Dof, n: Vec3, at: Vec3, mut state: BondState, steps: usize) -> Self {
        match dof {
            Dof::Normal => {}
            Dof::Twist => state.twist_angle = at.into(),
            Dof::Bend => state.bend_angle = at.into(),
        }
        let mut d = Drive {
            m,
            dof,
            n,
            state,
            at,
            load: Vec3::zeros(),
            work: 0.0,
            gross: 0.0,
            quadrature: 0.0,
            steps,
        };
        d.load = d.advance(Vec3::zeros());
        d
    }

    fn advance(&mut self, by: Vec3) -> Vec3 {
        let (velocity, spin, delta) = match self.dof {
            Dof::Normal => (by * (-1.0 / DT), Vec3::zeros(), (self.at + by).dot(&self.n)),
            _ => (Vec3::zeros(), by * (1.0 / DT), self.at.dot(&self.n)),
        };
        let kin = PairKinematics {
            x_i: (self.n * (R0 - delta)).into(),
            v_i: velocity.into(),
            w_i: spin.into(),
            ..pair_at(0.0)
        };
        let out = step(&self.m, &kin, DT, &mut self.state);
        match self.dof {
            Dof::Normal => -v3(out.force_i),
            _ => v3(out.torque_i),
        }
    }

    /// Straight to `target` in `self.steps` steps.
    fn to(&mut self, target: Vec3) {
        let by = (target - self.at) * (1.0 / self.steps as f64);
        let mut g = vec![self.beyond(-by).dot(&by), self.load.dot(&by)];
        for k in 0..self.steps {
            let load = self.advance(by);
            self.at = if k + 1 == self.steps { target } else { self.at + by };
            self.work += 0.5 * (self.load + load).dot(&by);
            self.gross += 0.5 * (self.load.norm() + load.norm()) * by.norm();
            self.load = load;
            g.push(load.dot(&by));
            // The deformation the bond sees is known to a few roundings of
            // the numbers it is computed from: the angle's, or, for the
            // normal law, the centre distance's.
            let size = match self.dof {
                Dof::Normal => R0,
                _ => self.at.norm(),
            };
            self.quadrature += 4.0 * f64::EPSILON * size * load.norm();
        }
        g.push(self.beyond(by).dot(&by));
        self.quadrature += g
            .windows(3)
            .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs())
            .sum::<f64>()
            / 4.0;
    }

    /// The load one step `by` away, the bond itself left where it is.
    fn beyond(&self, by: Vec3) -> Vec3 {
        let mut copy = self.clone();
        copy.advance(by)
    }

    /// The energy stored now.
    fn stored(&self) -> f64 {
        let delta = match self.dof {
            Dof::Normal => self.at.dot(&self.n),
            _ => 0.0,
        };
        self.m
            .stored_energy(&self.state, self.n.into(), delta, RADIUS, RADIUS)
            .total()
    }
}

/// Where a closed path of the bending angle stays at its history `beta`
/// (length `lead`), `beta_opp = opp`: the disc inside both extremes (region
/// 0 and 3: the one a path crosses sides in), the leading half disc (1) or
/// the opposite one (2) (each convex, so its straight
/// legs stay inside). `(radius, angle)` fractions place a vertex.
fn bend_vertex(region: u8, lead: f64, opp: f64, (r, a): (f64, f64), e1: Vec3, e2: Vec3) -> Vec3 {
    use std::f64::consts::PI;
    let (radius, angle) = match region {
        1 => (lead, -0.5 * PI + 0.01 + (PI - 0.02) * a),
        2 => (opp, 0.5 * PI + 0.01 + (PI - 0.02) * a),
        _ => (lead.min(opp), 2.0 * PI * a),
    };
    // Uniform over the area: most vertices where the two sides' laws
    // differ, between the reverse branch and the extreme.
    let x = 0.97 * radius * r.sqrt();
    e1 * (x * angle.cos()) + e2 * (x * angle.sin())
}

/// The bending history and a closed path inside it, from the strategy's
/// numbers: `(bond, start state, vertices)`.
fn bend_case(
    n: [f64; 3],
    (lead, opp_ratio, turn): (f64, f64, f64),
    region: u8,
    points: &[(f64, f64)],
) -> (Vec3, BondState, Vec<Vec3>) {
    let n = axis(n);
    let e1 = across(n);
    let e2 = n.cross(&e1);
    let e1r = e1 * turn.cos() + e2 * turn.sin();
    let e2r = n.cross(&e1r);
    let opp = opp_ratio * lead;
    let mut state = bond_at(R0);
    state.bend_history = (e1r * lead).into();
    state.bend_opposite = opp;
    let path = points
        .iter()
        .map(|&p| bend_vertex(region, lead, opp, p, e1r, e2r))
        .collect();
    (n, state, path)
}

/// Drives `path` (closed back to its first vertex when `closed`) from its
/// first vertex, `steps` a leg.
fn drive(
    m: &BondModel,
    dof: Dof,
    n: Vec3,
    state: BondState,
    path: &[Vec3],
    closed: bool,
    steps: usize,
) -> Drive {
    let mut d = Drive::new(m.clone(), dof, n, path[0], state, steps);
    for &p in &path[1..] {
        d.to(p);
    }
    if closed {
        d.to(path[0]);
    }
    d
}

/// What the work on the driver exceeds the stored energy released by
/// (`work - released`), with the bound of its quadrature error and
/// round-off. A law that made energy would show a surplus that does not
/// shrink with the step; the quadrature's does.
fn surplus(
    m: &BondModel,
    dof: Dof,
    n: Vec3,
    state: BondState,
    path: &[Vec3],
    closed: bool,
) -> (f64, f64, Drive) {
    let start = Drive::new(m.clone(), dof, n, path[0], state, STEPS);
    let before = start.stored();
    let d = drive(m, dof, n, state, path, closed, STEPS);
    let excess = d.work - (before - d.stored());
    let bound = d.quadrature + ROUND_OFF * (d.gross + before.abs());
    (excess, bound, d)
}

fn history(s: &BondState) -> [f64; 5] {
    [
        s.delta_max,
        s.delta_min,
        s.twist_max,
        s.twist_min,
        s.bend_opposite,
    ]
}

/// The same history to round-off; the bending history is a vector kept
/// across the bond, so its round-off is relative to its length, not to
/// each component.
fn same_history(a: &BondState, b: &BondState) -> bool {
    let close = |x: f64, y: f64, size: f64| (x - y).abs() <= 1e-12 * size;
    let (ha, hb) = (v3(a.bend_history), v3(b.bend_history));
    history(a)
        .iter()
        .zip(&history(b))
        .all(|(&x, &y)| close(x, y, x.abs() + y.abs()))
        && close((ha - hb).norm(), 0.0, ha.norm() + hb.norm())
}

/// Loops of every kind ([`stiffness_loop`]), and half of them mild
/// (`ku <= 4 k`, `kc <= k/2`): their unloading branch spans much of the
/// history, where the two sides' laws differ (with `ku = 100 k` it spans
/// the last percent).
fn loops() -> impl Strategy<Value = (f64, f64, f64)> {
    let mild = (8.0f64..13.0, 1.0f64..4.0, 0.0f64..0.5).prop_map(|(e, ratio, kc)| {
        let k = 10f64.powf(e);
        (k, k * ratio, k * kc)
    });
    prop_oneof![stiffness_loop(), mild]
}

fn path_points(count: std::ops::Range<usize>) -> impl Strategy<Value = Vec<(f64, f64)>> {
    prop::collection::vec((0.0f64..1.0, 0.0f64..1.0), count)
}

/// Twisting or normal deformations at a fixed history: signed values in
/// `[lo, hi]` along `n`.
fn line_path(n: Vec3, lo: f64, hi: f64, fractions: &[(f64, f64)]) -> Vec<Vec3> {
    fractions
        .iter()
        .map(|&(f, _)| n * (0.97 * (lo + (hi - lo) * f)))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn bending_over_a_closed_path_at_a_fixed_history_does_no_work_on_the_driver(
        n in vec3(1.0),
        law in loops(),
        history_size in (1e-4f64..2e-3, 0.05f64..1.5, 0.0f64..6.3),
        region in 0u8..4,
        points in path_points(2..6),
    ) {
        let (n, start, path) = bend_case(n, history_size, region, &points);
        let (work, bound, d) = surplus(&only(Dof::Bend, law, 0.0, false), Dof::Bend, n, start, &path, true);
        prop_assert!(same_history(&d.state, &start), "the path moved the history");
        prop_assert!(work <= bound, "work on the driver {} (quadrature {}, gross {})", work, bound, d.gross);
    }

    #[test]
    fn bending_with_history_reset_over_a_closed_path_in_its_leading_half_does_no_work(
        n in vec3(1.0),
        law in loops(),
        history_size in (1e-4f64..2e-3, 0.0f64..6.3),
        points in path_points(2..6),
    ) {
        // With the reset the opposite side holds no history (beta_opp = 0):
        // a path stays at its history in the leading half disc.
        let (n, start, path) = bend_case(n, (history_size.0, 0.0, history_size.1), 1, &points);
        let (work, bound, d) = surplus(&only(Dof::Bend, law, 0.0, true), Dof::Bend, n, start, &path, true);
        prop_assert!(same_history(&d.state, &start), "the path moved the history");
        prop_assert!(work <= bound, "work on the driver {} (quadrature {}, gross {})", work, bound, d.gross);
    }

    #[test]
    fn twisting_over_a_closed_path_at_a_fixed_history_does_no_work_on_the_driver(
        n in vec3(1.0),
        law in loops(),
        (hi, lo) in (0.0f64..2e-3, -2e-3f64..0.0),
        reset in any::<bool>(),
        points in path_points(2..6),
    ) {
        let n = axis(n);
        // With the reset only one side keeps its extreme.
        let (hi, lo) = if reset { (hi, 0.0) } else { (hi, lo) };
        let mut start = bond_at(R0);
        (start.twist_max, start.twist_min) = (hi, lo);
        let path = line_path(n, lo, hi, &points);
        let (work, bound, d) = surplus(&only(Dof::Twist, law, 0.0, reset), Dof::Twist, n, start, &path, true);
        prop_assert!(same_history(&d.state, &start), "the path moved the history");
        prop_assert!(work <= bound, "work on the driver {} (quadrature {}, gross {})", work, bound, d.gross);
    }

    #[test]
    fn the_normal_law_over_a_closed_path_at_a_fixed_history_does_no_work_on_the_driver(
        n in vec3(1.0),
        law in loops(),
        (hi, lo) in (0.0f64..2e-6, -2e-6f64..0.0),
        eps in prop_oneof![Just(0.0), 1e-9f64..1e-6],
        reset in any::<bool>(),
        points in path_points(2..6),
    ) {
        let n = axis(n);
        let (hi, lo) = if reset { (hi, 0.0) } else { (hi, lo) };
        let mut start = bond_at(R0);
        (start.delta_max, start.delta_min) = (hi, lo);
        let path = line_path(n, lo, hi, &points);
        let (work, bound, d) = surplus(&only(Dof::Normal, law, eps, reset), Dof::Normal, n, start, &path, true);
        prop_assert!(same_history(&d.state, &start), "the path moved the history");
        prop_assert!(work <= bound, "work on the driver {} (quadrature {}, gross {})", work, bound, d.gross);
    }

    #[test]
    fn every_load_is_the_gradient_of_the_stored_energy_at_a_fixed_history(
        n in vec3(1.0),
        law in loops(),
        history_size in (1e-4f64..2e-3, 0.05f64..1.5, 0.0f64..6.3),
        region in 0u8..3,
        points in path_points(2..5),
        eps in prop_oneof![Just(0.0), 1e-9f64..1e-6],
    ) {
        // Open paths: the work on the driver is what the stored energy lost.
        let (axis_n, bend_start, bend_path) = bend_case(n, history_size, region, &points);
        let (lead, ratio, _) = history_size;
        let mut line_start = bond_at(R0);
        (line_start.twist_max, line_start.twist_min) = (lead, -ratio * lead);
        (line_start.delta_max, line_start.delta_min) = (1e-3 * lead, -1e-3 * ratio * lead);
        let twist_path = line_path(axis_n, -ratio * lead, lead, &points);
        let normal_path = line_path(axis_n, -1e-3 * ratio * lead, 1e-3 * lead, &points);
        for (dof, start, path) in [
            (Dof::Bend, bend_start, bend_path),
            (Dof::Twist, line_start, twist_path),
            (Dof::Normal, line_start, normal_path),
        ] {
            let (surplus, bound, d) = surplus(&only(dof, law, eps, false), dof, axis_n, start, &path, false);
            prop_assert!(
                surplus.abs() <= bound,
                "{:?}: work on the driver beyond the stored energy released {} (quadrature {}, gross {})",
                dof, surplus, bound, d.gross
            );
        }
    }

    #[test]
    fn a_path_that_moves_the_bending_history_dissipates(
        n in vec3(1.0),
        law in loops(),
        history_size in (1e-4f64..2e-3, 0.0f64..1.5, 0.0f64..6.3),
        points in prop::collection::vec((0.0f64..2.5, 0.0f64..1.0), 2..6),
    ) {
        // Anywhere up to 2.5 times the leading extreme: the history turns
        // and grows on both sides; the work on the driver never exceeds
        // the stored energy released.
        let (n, start, _) = bend_case(n, history_size, 0, &[]);
        let (e1, lead) = (v3(start.bend_history) * (1.0 / history_size.0), history_size.0);
        let e2 = n.cross(&e1);
        let path: Vec<Vec3> = points
            .iter()
            .map(|&(r, a)| {
                let a = a * std::f64::consts::TAU;
                (e1 * a.cos() + e2 * a.sin()) * (r * lead)
            })
            .collect();
        let (surplus, bound, d) = surplus(&only(Dof::Bend, law, 0.0, false), Dof::Bend, n, start, &path, false);
        prop_assert!(
            surplus <= bound,
            "work on the driver beyond the stored energy released {} (quadrature {}, gross {})",
            surplus, bound, d.gross
        );
    }

    #[test]
    fn bending_in_one_plane_is_the_signed_two_sided_law(
        n in vec3(1.0),
        turn in 0.0f64..6.3,
        law in loops(),
        reset in any::<bool>(),
        targets in prop::collection::vec(-2e-3f64..2e-3, 1..6),
    ) {
        let n = axis(n);
        let e1 = across(n);
        let line = e1 * turn.cos() + n.cross(&e1) * turn.sin();
        let m = only(Dof::Bend, law, 0.0, reset);
        let inertia = section(m.params.lambda, RADIUS, RADIUS).inertia;
        let mut reference = SignedLaw::default();
        let mut state = bond_at(R0);
        let mut at = 0.0;
        for &target in &targets {
            let by = (target - at) / STEPS as f64;
            for _ in 0..STEPS {
                let kin = PairKinematics {
                    x_i: (n * R0).into(),
                    w_i: (line * (by / DT)).into(),
                    ..pair_at(0.0)
                };
                let out = step(&m, &kin, DT, &mut state);
                at += by;
                let s = v3(state.bend_angle).dot(&line);
                let (f, _, _) = reference.value(law, s, reset);
                let want = line * (-f * inertia);
                // The angle is a sum of steps, known to round-off of the
                // largest angle; where the unloading line crosses zero
                // (two terms cancelling) that is all the torque is known to.
                let floor = law.0.max(law.1).max(law.2) * inertia * 1e-13 * 2e-3;
                prop_assert!(
                    (v3(out.torque_i) - want).norm() <= 1e-12 * want.norm() + floor,
                    "angle {}: torque {:?}, signed law {:?}", s, out.torque_i, want
                );
            }
        }
    }
}

#[test]
fn bending_around_a_square_after_a_set_up_bend_does_no_work_on_the_driver() {
    // The scene of shared/repro/energy/in.bendcycle: ku = 2 k, kc = k/10,
    // a set-up bend to 0.01 rad along the first axis, then squares of
    // half-width 5e-3 rad across it, run both ways.
    let n = axis([0.36, -0.48, 0.8]);
    let e1 = across(n);
    let e2 = n.cross(&e1);
    let law = (1e10, 2e10, 1e9);
    let m = only(Dof::Bend, law, 0.0, false);
    let mut start = bond_at(R0);
    start.bend_history = (e1 * 0.01).into();
    start.bend_opposite = 0.005 * 2f64.sqrt();
    let b = 0.005;
    let corners = [(0.0, 0.0), (b, 0.0), (b, b), (-b, b), (-b, 0.0)];
    for direction in [1.0, -1.0] {
        let path: Vec<Vec3> = corners
            .iter()
            .map(|&(x, y)| e1 * (direction * x) + e2 * y)
            .collect();
        let (work, bound, d) = surplus(&m, Dof::Bend, n, start, &path, true);
        assert!(same_history(&d.state, &start), "the square moved the history");
        assert!(
            work <= bound,
            "direction {direction}: work on the driver {work:e} (quadrature {bound:e}, gross {:e})",
            d.gross
        );
    }
}
