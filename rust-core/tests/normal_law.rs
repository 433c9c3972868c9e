//! The six-branch normal law (docs/models/bond-nonlinear.md eq. 4-6), its history and its
//! continuity.

use granbond::bond::hysteresis::Loop;
use granbond::bond::normal_law::NormalLaw;

/// The spec's table, transcribed literally (with its `delta_c1`, `delta_c2`),
/// as an independent oracle for the loop form used by the crate.
fn spec_table(d: f64, dmax: f64, dmin: f64, c: (f64, f64, f64), t: (f64, f64, f64)) -> f64 {
    let (k1, ku1, kc1) = c;
    let (k2, ku2, kc2) = t;
    let dc1 = ((ku1 - k1) / (ku1 + kc1)).powi(2) * dmax;
    let dc2 = (ku2 - k2) / (ku2 + kc2) * dmin;
    if d < dmin {
        k2 * d
    } else if d < dc2 {
        ku2 * d + (k2 - ku2) * dmin
    } else if d < 0.0 {
        -kc2 * d
    } else if d < dc1 {
        -kc1 * d.abs().sqrt()
    } else if d < dmax {
        ku1 * d.abs().sqrt() + (k1 - ku1) * dmax.abs().sqrt()
    } else {
        k1 * d.abs().sqrt()
    }
}

const C: (f64, f64, f64) = (1.0, 3.0, 0.5);
const T: (f64, f64, f64) = (2.0, 5.0, 1.0);

fn law(history_reset: bool) -> NormalLaw {
    NormalLaw::new(
        Loop::new(C.0, C.1, C.2),
        Loop::new(T.0, T.1, T.2),
        0.0,
        history_reset,
    )
}

/// Stress after updating the history with `d`, as the kernel does.
fn stress_at(law: &NormalLaw, d: f64, hist: &mut (f64, f64)) -> f64 {
    *hist = law.update_history(d, hist.0, hist.1);
    law.stress(d, hist.0, hist.1, true, true)
}

#[test]
fn hand_computed_values_on_each_branch() {
    // Compression k=1, ku=3, kc=0.5; dmax = 4: c = 2/3.5, dc1 = c^2 4 = 1.306.
    let l = law(false);
    let s = |d: f64, dmax: f64, dmin: f64| l.stress(d, dmax, dmin, true, true);
    assert_eq!(s(4.0, 4.0, 0.0), 2.0); // virgin: 1 * sqrt 4
    assert!((s(2.25, 4.0, 0.0) - 0.5).abs() < 1e-15); // unloading: 3*1.5 + (1-3)*2
    assert!((s(0.25, 4.0, 0.0) + 0.25).abs() < 1e-15); // reverse: -0.5*0.5
                                                       // Tension k=2, ku=5, kc=1; dmin = -2: dc2 = 3/6 * -2 = -1.
    assert_eq!(s(-3.0, 0.0, -3.0), -6.0); // virgin: 2 * -3
    assert!((s(-1.5, 0.0, -2.0) - (5.0 * -1.5 + (2.0 - 5.0) * -2.0)).abs() < 1e-15); // unloading: -1.5
    assert!((s(-0.5, 0.0, -2.0) - 0.5).abs() < 1e-15); // reverse: -1 * -0.5
}

#[test]
fn continuous_at_every_branch_boundary() {
    let l = law(false);
    let (dmax, dmin) = (4.0, -2.0);
    let dc1 = ((C.1 - C.0) / (C.1 + C.2)).powi(2) * dmax;
    let dc2 = (T.1 - T.0) / (T.1 + T.2) * dmin;
    for b in [dmin, dc2, 0.0, dc1, dmax] {
        let eps = 1e-10;
        let below = l.stress(b - eps, dmax, dmin.min(b - eps), true, true);
        let above = l.stress(b + eps, dmax.max(b + eps), dmin, true, true);
        // sqrt(eps) = 1e-5 is the largest legitimate change across 2 eps.
        assert!((below - above).abs() < 1e-4, "jump at {b}: {below} vs {above}");
    }
}

#[test]
fn the_loop_form_equals_the_spec_table_everywhere() {
    let l = law(false);
    for &(dmax, dmin) in &[
        (4.0, -2.0),
        (0.3, -7.0),
        (1e-6, -1e-6),
        (0.0, 0.0),
        (9.0, 0.0),
        (0.0, -3.0),
    ] {
        for k in 0..=400 {
            let d = dmin + (dmax - dmin) * k as f64 / 400.0;
            let ours = l.stress(d, dmax, dmin, true, true);
            let spec = spec_table(d, dmax, dmin, C, T);
            assert!(
                (ours - spec).abs() <= 1e-12 * (1.0 + spec.abs()),
                "d={d}: {ours} vs {spec}"
            );
        }
    }
}

#[test]
fn load_unload_reload_cycle_traces_the_spec_loop() {
    let l = law(false);
    let mut hist = (0.0, 0.0);
    let mut path = Vec::new();
    let leg = |a: f64, b: f64| (0..=100).map(move |k| a + (b - a) * k as f64 / 100.0);
    path.extend(leg(0.0, 4.0)); // virgin compression
    path.extend(leg(4.0, -2.0)); // unload through zero into tension
    path.extend(leg(-2.0, 1.0)); // back
    path.extend(leg(1.0, 9.0)); // reload past the old maximum
    let mut previous_max = 0.0f64;
    for d in path {
        let f = stress_at(&l, d, &mut hist);
        let spec = spec_table(d, hist.0, hist.1, C, T);
        assert!(
            (f - spec).abs() <= 1e-12 * (1.0 + spec.abs()),
            "d={d}: {f} vs {spec}"
        );
        assert!(hist.1 <= d && d <= hist.0, "history brackets delta");
        assert!(
            hist.0 >= previous_max,
            "dmax never decreases without history reset"
        );
        previous_max = hist.0;
    }
    // Reloading past dmax = 4 returns to the virgin curve: F(9) = sqrt(9).
    assert_eq!(stress_at(&l, 9.0, &mut hist), 3.0);
}

#[test]
fn unloading_leaves_a_permanent_set_with_zero_force() {
    // After compression to dmax the force vanishes on the unloading line at
    // sqrt(d) = (ku - k)/ku sqrt(dmax): the permanent set.
    let l = law(false);
    let dmax: f64 = 4.0;
    let set = ((C.1 - C.0) / C.1 * dmax.sqrt()).powi(2);
    assert!(l.stress(set, dmax, 0.0, true, true).abs() < 1e-14);
    assert!(l.stress(set * 1.01, dmax, 0.0, true, true) > 0.0);
    assert!(l.stress(set * 0.99, dmax, 0.0, true, true) < 0.0);
}

#[test]
fn history_is_kept_by_default_and_reset_on_sign_change_as_an_option() {
    let (kept, reset) = (law(false), law(true));
    let (mut hk, mut hr) = ((0.0, 0.0), (0.0, 0.0));
    for d in [4.0, -1.0, 1.0] {
        stress_at(&kept, d, &mut hk);
        stress_at(&reset, d, &mut hr);
    }
    assert_eq!(hk, (4.0, -1.0));
    // The reference code zeroes dmax when d < 0 and dmin when d > 0.
    assert_eq!(hr, (1.0, 0.0));
    // So reloading to 1 after tension is on the unloading line in the
    // default and on the virgin curve with the reset.
    assert!(stress_at(&kept, 1.0, &mut hk) < 1.0);
    assert_eq!(stress_at(&reset, 1.0, &mut hr), 1.0);
}

#[test]
fn switched_off_halves_give_no_force() {
    let l = law(false);
    assert_eq!(l.stress(-1.0, 0.0, -1.0, false, true), 0.0);
    assert_eq!(l.stress(1.0, 1.0, 0.0, true, false), 0.0);
    assert!(l.stress(1.0, 1.0, 0.0, false, true) > 0.0);
}

#[test]
fn linear_regularisation_is_continuous_and_bounds_the_stiffness() {
    let eps = 1e-2;
    let l = NormalLaw::new(Loop::new(C.0, C.1, C.2), Loop::new(T.0, T.1, T.2), eps, false);
    // Continuous at eps, linear below with slope k / sqrt(eps).
    let below = l.stress(eps * (1.0 - 1e-12), eps, 0.0, true, true);
    assert!((below - C.0 * eps.sqrt()).abs() < 1e-12);
    let slope = l.stress(eps / 10.0, eps / 10.0, 0.0, true, true) / (eps / 10.0);
    assert!((slope - C.0 / eps.sqrt()).abs() < 1e-9);
    // Above eps it is the square root law.
    assert!((l.stress(0.25, 0.25, 0.0, true, true) - 0.5).abs() < 1e-15);
}
