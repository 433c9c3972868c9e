//! The bond output as engines keep it in the pair's history
//! (`bond::output_slots`), and the bond centre engines log.

use granbond_test_support as common;

use common::strategies::vec3;
use granbond::bond::output_slots::{load_output, store_output, BOND_OUTPUT_LEN, BOND_OUTPUT_SLOTS};
use granbond::bond::{BondOutput, BondStatus, BreakMode};
use granbond::kinematics::bond_centre;
use granbond::state_layout::swap_state;
use proptest::prelude::*;

fn output(force_i: [f64; 3], torque_i: [f64; 3], torque_j: [f64; 3], sigma: f64, tau: f64) -> BondOutput {
    BondOutput {
        force_i,
        torque_i,
        torque_j,
        normal_force: 3.5,
        sigma,
        tau,
        delta: -1e-6,
        status: BondStatus::Intact as i32,
        break_mode: BreakMode::None as i32,
    }
}

/// The same output seen from sphere `j`: the force on `j`, the torques
/// traded.
fn seen_from_j(o: &BondOutput) -> BondOutput {
    BondOutput {
        force_i: o.force_i.map(|f| -f),
        torque_i: o.torque_j,
        torque_j: o.torque_i,
        ..*o
    }
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    common::norm([a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn output_strategy() -> impl Strategy<Value = BondOutput> {
    (vec3(1e3), vec3(1.0), vec3(1.0), 0.0f64..1e8, 0.0f64..1e8)
        .prop_map(|(f, ti, tj, sigma, tau)| output(f, ti, tj, sigma, tau))
}

#[test]
fn the_slots_keep_the_names_and_swap_rules_engines_store_them_under() {
    // restart files and per-contact dumps know the slots by these names
    let want = [
        ("bond_force_x", true),
        ("bond_force_y", true),
        ("bond_force_z", true),
        ("bond_torque_1_x", false),
        ("bond_torque_1_y", false),
        ("bond_torque_1_z", false),
        ("bond_torque_2_x", false),
        ("bond_torque_2_y", false),
        ("bond_torque_2_z", false),
        ("bond_side", true),
        ("bond_sigma", false),
        ("bond_tau", false),
    ];
    let got: Vec<(&str, bool)> = BOND_OUTPUT_SLOTS
        .iter()
        .map(|s| (s.name, s.flips_on_swap))
        .collect();
    assert_eq!(got, want);
    assert_eq!(BOND_OUTPUT_LEN, want.len());
}

#[test]
fn store_then_load_gives_back_the_loads() {
    let o = output(
        [1.5, -2.25, 0.125],
        [3.0, -0.5, 7.75],
        [-1.25, 4.0, 0.375],
        1.0e6,
        2.5e5,
    );
    let slots = store_output(&o);
    assert_eq!(
        slots,
        [1.5, -2.25, 0.125, 3.0, -0.5, 7.75, -1.25, 4.0, 0.375, 1.0, 1.0e6, 2.5e5]
    );
    let back = load_output(&slots);
    assert_eq!(back.force_i, o.force_i);
    assert_eq!(back.torque_i, o.torque_i);
    assert_eq!(back.torque_j, o.torque_j);
    assert_eq!((back.sigma, back.tau), (o.sigma, o.tau));
    assert_eq!(back.status, BondStatus::Intact as i32);
    assert_eq!(back.break_mode, BreakMode::None as i32);
    assert_eq!((back.normal_force, back.delta), (0.0, 0.0));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// A run's setup pass applies what was loaded: it must be the load the
    /// force pass applied, to the last bit, or a second `run` does not
    /// continue the first.
    #[test]
    fn store_and_load_give_back_every_load_bit_for_bit(o in output_strategy()) {
        let back = load_output(&store_output(&o));
        prop_assert_eq!(bits(&back.force_i), bits(&o.force_i));
        prop_assert_eq!(bits(&back.torque_i), bits(&o.torque_i));
        prop_assert_eq!(bits(&back.torque_j), bits(&o.torque_j));
        prop_assert_eq!((back.sigma.to_bits(), back.tau.to_bits()), (o.sigma.to_bits(), o.tau.to_bits()));
        prop_assert_eq!((back.status, back.break_mode), (BondStatus::Intact as i32, BreakMode::None as i32));
    }

    /// The invariant the swap flags stand for: the engine negates the
    /// flagged slots when the pair is seen from the other sphere, which
    /// must give, bit for bit, the output seen from that sphere; swapped
    /// back, the slots are those stored.
    #[test]
    fn the_flagged_slots_negated_are_the_output_seen_from_the_other_sphere(o in output_strategy()) {
        let stored = store_output(&o);
        let mut swapped = stored;
        swap_state(&BOND_OUTPUT_SLOTS, &mut swapped);
        let back = load_output(&swapped);
        let other = seen_from_j(&o);
        prop_assert_eq!(bits(&back.force_i), bits(&other.force_i));
        prop_assert_eq!(bits(&back.torque_i), bits(&other.torque_i));
        prop_assert_eq!(bits(&back.torque_j), bits(&other.torque_j));
        swap_state(&BOND_OUTPUT_SLOTS, &mut swapped);
        prop_assert_eq!(bits(&swapped), bits(&stored));
    }

    #[test]
    fn the_bond_centre_divides_the_centre_line_in_the_ratio_of_the_radii(
        x_i in vec3(1e-2),
        x_j in vec3(1e-2),
        radius_i in 1e-5f64..1e-2,
        radius_j in 1e-5f64..1e-2,
    ) {
        let d = distance(x_i, x_j);
        prop_assume!(d > 1e-6);
        let c = bond_centre(x_i, x_j, radius_i, radius_j);
        let (to_i, to_j) = (distance(c, x_i), distance(c, x_j));
        let tol = 1e-12 * (d + common::norm(x_i) + common::norm(x_j));
        let sum = radius_i + radius_j;
        prop_assert!((to_i - radius_i / sum * d).abs() <= tol, "|c - x_i| = {to_i}");
        prop_assert!((to_j - radius_j / sum * d).abs() <= tol, "|c - x_j| = {to_j}");
        // on the segment: the two distances add up to its length
        prop_assert!((to_i + to_j - d).abs() <= tol);
        let w = radius_j / sum;
        for k in 0..3 {
            prop_assert_eq!(c[k].to_bits(), (x_j[k] + w * (x_i[k] - x_j[k])).to_bits());
        }
    }

    #[test]
    fn the_centre_of_a_wall_bond_is_the_wall_point(x_i in vec3(1e-2), wall in vec3(1e-2), radius_i in 1e-5f64..1e-2) {
        prop_assert_eq!(bond_centre(x_i, wall, radius_i, 0.0), wall);
    }
}

#[test]
fn equal_spheres_are_bonded_at_the_midpoint() {
    let c = bond_centre([2.0, -4.0, 6.0], [0.0, 0.0, 1.0], 0.5, 0.5);
    assert_eq!(c, [1.0, -2.0, 3.5]);
}
