//! The time-step check of the plain square root, through the C ABI: where
//! bonds break in compression, the recommended step keeps the rattle
//! (`compression_noise_floor`) `RATTLE_MARGIN` below the compression break
//! threshold; where bonds rest at zero compression, the check warns above
//! the measured step at which they gain no energy (`rest_timestep`), and
//! never at a step below it.

use granbond::bond::timestep::{RATTLE_MARGIN, RECOMMENDED_FRACTION};
use granbond::bond::{BondModel, BondParams};
use granbond::ffi::checks::{granbond_bond_timestep_check, CheckReport};
use granbond::ffi::Status;
use granbond::timestep_check::{short, TypeBodies};
use std::ffi::CStr;

const R: f64 = 1e-3;

fn mass() -> f64 {
    2500.0 * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3)
}

/// A bond with stress breakage and the plain square root; every stiffness
/// from one value, twice it unloading, a tenth of it reverse; damped enough
/// that bonds at rest gain no energy up to the recommended step.
fn bond() -> BondParams {
    let k = 1e10;
    BondParams {
        lambda: 0.6,
        k_fn1: k,
        ku_fn1: 2.0 * k,
        kc_fn1: 0.1 * k,
        k_fn2: 3.0 * k,
        ku_fn2: 6.0 * k,
        kc_fn2: 0.3 * k,
        k_ft: k,
        k_tn: k,
        ku_tn: 2.0 * k,
        kc_tn: 0.1 * k,
        k_tt: k,
        ku_tt: 2.0 * k,
        kc_tt: 0.1 * k,
        stress_break: 1,
        max_sigma: 2e5,
        max_tau: 2e5,
        damping: 1,
        eta_fn: 0.1,
        ..BondParams::default()
    }
}

#[test]
fn at_the_rattle_step_the_floor_is_the_margin_below_the_threshold() {
    let model = BondModel::new(bond()).unwrap();
    let m = mass();
    let threshold = model.compression_break_threshold();
    assert_eq!(threshold, (2e5f64 / 1e10).powi(2));
    let step = model.rattle_timestep(R, R, m, m);
    let floor = model.compression_noise_floor(step, R, R, m, m);
    assert!(
        (floor * RATTLE_MARGIN / threshold - 1.0).abs() < 1e-12,
        "{floor} vs {threshold}"
    );
    let critical = model.critical_timestep(R, R, m, m);
    assert!(step < RECOMMENDED_FRACTION * critical);
    assert_eq!(model.recommended_timestep(R, R, m, m), step);
}

#[test]
fn no_rattle_limit_without_breakage_in_compression_or_with_the_regularisation() {
    let m = mass();
    for p in [
        BondParams {
            compression_linear_below: 6e-7,
            ..bond()
        },
        BondParams {
            stress_break: 0,
            max_distance: 3e-3,
            ..bond()
        },
        BondParams {
            max_sigma: f64::INFINITY,
            ..bond()
        },
        BondParams {
            compression: 0,
            ..bond()
        },
    ] {
        let model = BondModel::new(p).unwrap();
        assert!(model.rattle_timestep(R, R, m, m).is_infinite(), "{p:?}");
        let critical = model.critical_timestep(R, R, m, m);
        assert_eq!(
            model.recommended_timestep(R, R, m, m),
            RECOMMENDED_FRACTION * critical
        );
    }
}

fn check(dt: f64, naming: i32, units: &CStr) -> CheckReport {
    check_bond(bond(), dt, naming, units)
}

fn check_bond(params: BondParams, dt: f64, naming: i32, units: &CStr) -> CheckReport {
    let model = BondModel::new(params).unwrap();
    // (ntypes + 1)^2 entries, types 1 and 1 at 1 * 2 + 1
    let table = [
        std::ptr::null(),
        std::ptr::null(),
        std::ptr::null(),
        &model as *const BondModel,
    ];
    let m = mass();
    let bodies = [
        TypeBodies::none(),
        TypeBodies {
            radius_min: R,
            radius_max: R,
            mass_min: m,
        },
    ];
    let mut report: CheckReport = unsafe { std::mem::zeroed() };
    let status = unsafe {
        granbond_bond_timestep_check(
            table.as_ptr(),
            1,
            bodies.as_ptr(),
            dt,
            naming,
            units.as_ptr(),
            c"cohesion bond/nonlinear".as_ptr(),
            &mut report,
        )
    };
    assert_eq!(status, Status::Ok);
    report
}

fn text(report: &CheckReport) -> String {
    unsafe { CStr::from_ptr(report.message.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

#[test]
fn the_warning_names_the_rattle_its_parameters_and_both_remedies() {
    let model = BondModel::new(bond()).unwrap();
    let m = mass();
    let step = model.rattle_timestep(R, R, m, m);
    assert_eq!(check(0.95 * step, 1, c"si").level, 0);
    let report = check(1.3e-7, 1, c"si");
    assert_eq!(report.level, 1);
    assert_eq!(report.recommended, step);
    let msg = text(&report);
    for part in [
        "exceeds the recommended step",
        "rattle",
        "(maxSigmaBondnonlinear / stiffnessPerUnitAreaK_fn1)^2 = 4e-10 m",
        &format!("Remedies: timestep <= {} s", short(step)),
        "the linear regularisation compressionLinearBelowBondnonlinear",
        "the limit of one bond between two free spheres",
        "for z = 6",
    ] {
        assert!(msg.contains(part), "no '{part}' in: {msg}");
    }
    assert!(msg.contains("this time step for z <= "), "{msg}");
    let far = text(&check(1e-5, 1, c"si"));
    assert!(far.contains("this time step for no sphere"), "{far}");
    let lammps = text(&check(1.3e-7, 0, c"si"));
    assert!(
        lammps.contains("(max_sigma / k_fn1)^2") && lammps.contains("compression_linear_below"),
        "{lammps}"
    );
}

#[test]
fn the_warning_speaks_the_decks_units() {
    let msg = text(&check(1.3e-7, 0, c"micro"));
    assert!(
        msg.contains(" us ") && msg.contains(" um") && msg.contains(" pg"),
        "{msg}"
    );
    assert!(
        !msg.contains(" s ") && !msg.contains(" m ") && !msg.contains(" kg"),
        "{msg}"
    );
    let other = text(&check(1.3e-7, 0, c"lj"));
    assert!(other.contains("deck units"), "{other}");
}

#[test]
fn numbers_have_four_significant_digits() {
    assert_eq!(short(4.0343576522993926e-8), "4.034e-8");
    assert_eq!(short(1e-3), "1e-3");
    assert_eq!(short(2.5e-9), "2.5e-9");
    assert_eq!(short(f64::INFINITY), "inf");
}

/// An elastic bond (ku = k, kc = 0) without breakage or damping: its
/// bonds rest at zero compression, where the plain square root is stiffest.
fn elastic() -> BondParams {
    let k = 1e10;
    BondParams {
        ku_fn1: k,
        kc_fn1: 0.0,
        ku_fn2: 3.0 * k,
        kc_fn2: 0.0,
        ku_tn: k,
        kc_tn: 0.0,
        ku_tt: k,
        kc_tt: 0.0,
        stress_break: 0,
        max_distance: 3e-3,
        damping: 0,
        eta_fn: 0.0,
        ..bond()
    }
}

fn recommended(params: BondParams) -> f64 {
    let m = mass();
    BondModel::new(params).unwrap().recommended_timestep(R, R, m, m)
}

#[test]
fn elastic_bonds_at_rest_under_the_plain_square_root_are_warned_at_every_step() {
    let step = recommended(elastic());
    for (naming, clb) in [
        (0, "compression_linear_below"),
        (1, "compressionLinearBelowBondnonlinear"),
    ] {
        let report = check_bond(elastic(), 0.05 * step, naming, c"si");
        assert_eq!(report.level, 1);
        let msg = text(&report);
        for part in [
            "cannot be integrated stably at rest",
            &format!("down to 0.05 of the recommended step {} s", short(step)),
            &format!("the linear regularisation {clb}"),
            "6e-7 m (1e-3 of the bond radius",
        ] {
            assert!(msg.contains(part), "no '{part}' in: {msg}");
        }
        assert!(!msg.contains("Use timestep <="), "no step is stable: {msg}");
        assert!(msg.contains("is not stable for the stiffest bond"), "{msg}");
        assert!(!msg.contains("step 0e0 s"), "no step is stable: {msg}");
    }
}

#[test]
fn bonds_at_rest_with_little_hysteresis_are_warned_above_the_measured_fraction() {
    let p = BondParams {
        ku_fn1: 1.1 * elastic().k_fn1,
        ..elastic()
    };
    let step = recommended(p);
    let m = mass();
    let fraction = BondModel::new(p).unwrap().rest_stable_fraction();
    assert!(fraction > 0.0 && fraction < 1.0, "{fraction}");
    assert_eq!(check_bond(p, 0.95 * fraction * step, 0, c"si").level, 0);
    let report = check_bond(p, 1.05 * fraction * step, 0, c"si");
    assert_eq!(report.level, 1);
    assert_eq!(
        report.recommended,
        BondModel::new(p).unwrap().rest_timestep(R, R, m, m)
    );
    let msg = text(&report);
    for part in [
        &format!(
            "gain energy above {fraction} of the recommended step {} s",
            short(step)
        ),
        "ku_fn1/k_fn1 = 1.1, eta_fn = 0",
        "(the core's recommended step, set by the bonds at rest)",
    ] {
        assert!(msg.contains(part), "no '{part}' in: {msg}");
    }
}

#[test]
fn regularised_hysteretic_or_damped_bonds_are_not_warned_up_to_the_recommended_step() {
    let k = elastic().k_fn1;
    for p in [
        BondParams {
            compression_linear_below: 6e-7,
            ..elastic()
        },
        BondParams {
            ku_fn1: 3.0 * k,
            eta_fn: 0.001,
            damping: 1,
            ..elastic()
        },
        BondParams {
            eta_fn: 0.1,
            damping: 1,
            ..elastic()
        },
        BondParams {
            compression: 0,
            ..elastic()
        },
    ] {
        let report = check_bond(p, 0.99 * recommended(p), 0, c"si");
        assert_eq!(report.level, 0, "{p:?}: {}", text(&report));
    }
    // Smooth damping fades at the speeds of a bond at rest: it counts as none.
    let smooth = BondParams {
        eta_fn: 0.1,
        damping: 1,
        damping_smooth: 1,
        ..elastic()
    };
    assert_eq!(check_bond(smooth, 0.05 * recommended(smooth), 0, c"si").level, 1);
}
