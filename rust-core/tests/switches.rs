//! Each degree of freedom can be switched off; a switched-off part is
//! compiled out (its own kernel), and its result equals the full kernel with
//! that part's stiffness zeroed.

use granbond_test_support as common;

use common::*;
use granbond::bond::features::{BEND, COMPRESSION, DAMPING, SHEAR, SMOOTH, TENSION, TWIST};
use granbond::bond::{BondOutput, BondParams, BondState};
use granbond::kinematics::PairKinematics;

fn moving_pair(stretch: f64) -> (PairKinematics, BondState) {
    let kin = PairKinematics {
        x_i: [2.0 * RADIUS * (1.0 + stretch), 1e-6, 0.0],
        v_i: [0.01, 0.02, -0.01],
        w_i: [2.0, 1.0, -3.0],
        w_j: [-1.0, 0.0, 2.0],
        ..pair_at(0.0)
    };
    (kin, bond_at(2.0 * RADIUS))
}

fn outputs(p: BondParams, stretch: f64) -> (BondOutput, BondState) {
    let m = model(p);
    let (kin, mut s) = moving_pair(stretch);
    let mut out = BondOutput::default();
    for _ in 0..5 {
        out = step(&m, &kin, 1e-6, &mut s);
    }
    (out, s)
}

#[test]
fn switches_select_the_kernel_features() {
    let on = model(BondParams {
        damping: 1,
        eta_fn: 0.1,
        damping_smooth: 1,
        ..params()
    });
    assert_eq!(
        on.features,
        TENSION | COMPRESSION | SHEAR | TWIST | BEND | DAMPING | SMOOTH
    );
    let off = model(BondParams {
        tension: 0,
        compression: 0,
        shear: 0,
        twist: 0,
        bend: 0,
        ..params()
    });
    assert_eq!(off.features, 0);
    // Damping with all ratios zero changes nothing and is left out.
    assert_eq!(
        model(BondParams {
            damping: 1,
            ..params()
        })
        .features
            & DAMPING,
        0
    );
}

#[test]
fn reduced_kernels_equal_the_full_kernel_with_those_parts_zeroed() {
    let full = params();
    let cases: [(BondParams, BondParams); 3] = [
        (
            BondParams {
                twist: 0,
                bend: 0,
                ..full
            },
            BondParams {
                k_tn: 0.0,
                ku_tn: 0.0,
                kc_tn: 0.0,
                k_tt: 0.0,
                ku_tt: 0.0,
                kc_tt: 0.0,
                ..full
            },
        ),
        (BondParams { shear: 0, ..full }, BondParams { k_ft: 0.0, ..full }),
        (
            BondParams { tension: 0, ..full },
            BondParams {
                k_fn2: 0.0,
                ku_fn2: 0.0,
                kc_fn2: 0.0,
                ..full
            },
        ),
    ];
    for stretch in [1e-4, -1e-4] {
        for (reduced, zeroed) in cases {
            let (a, _) = outputs(reduced, stretch);
            let (b, _) = outputs(zeroed, stretch);
            assert_eq!(a.force_i, b.force_i);
            assert_eq!(a.torque_i, b.torque_i);
            assert_eq!(a.torque_j, b.torque_j);
            assert_eq!(a.sigma, b.sigma);
        }
    }
}

#[test]
fn a_switched_off_degree_of_freedom_exerts_nothing_and_keeps_no_history() {
    let (out, s) = outputs(
        BondParams {
            twist: 0,
            bend: 0,
            shear: 0,
            ..params()
        },
        1e-4,
    );
    assert_eq!(s.shear_force, [0.0; 3]);
    assert_eq!(s.twist_angle, [0.0; 3]);
    assert_eq!(s.bend_angle, [0.0; 3]);
    // Only the normal force remains: along the axis, no torque.
    assert!(out.force_i[0] < 0.0);
    assert_eq!(out.torque_i, [0.0; 3]);
    let (out, _) = outputs(
        BondParams {
            compression: 0,
            shear: 0,
            twist: 0,
            bend: 0,
            ..params()
        },
        -1e-4,
    );
    assert_eq!(out.force_i, [0.0; 3], "compression off: no force when compressed");
    let (out, _) = outputs(
        BondParams {
            tension: 0,
            shear: 0,
            twist: 0,
            bend: 0,
            ..params()
        },
        1e-4,
    );
    assert_eq!(out.force_i, [0.0; 3], "tension off: no force when stretched");
}
