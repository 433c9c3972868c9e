//! `granbond_bond_recommended_timestep`: the step engines warn above is the
//! core's safety fraction of the critical step, through the C ABI.

use granbond::bond::timestep::RECOMMENDED_FRACTION;
use granbond::bond::{BondModel, BondParams};
use granbond::ffi::bond::{granbond_bond_critical_timestep, granbond_bond_recommended_timestep};
use granbond::ffi::Status;

#[test]
fn recommended_step_is_the_safety_fraction_of_the_critical_step() {
    let model = BondModel::new(BondParams {
        k_fn2: 1e9,
        ku_fn2: 2e9,
        kc_fn2: 5e8,
        k_ft: 4e8,
        ..BondParams::default()
    })
    .unwrap();
    let (r, m) = (1e-3, 1e-5);
    let (mut critical, mut recommended) = (0.0, 0.0);
    unsafe {
        assert_eq!(
            granbond_bond_critical_timestep(&model, r, 0.5 * r, m, 0.3 * m, &mut critical),
            Status::Ok
        );
        assert_eq!(
            granbond_bond_recommended_timestep(&model, r, 0.5 * r, m, 0.3 * m, &mut recommended),
            Status::Ok
        );
    }
    assert!(critical.is_finite() && critical > 0.0);
    assert_eq!(recommended, RECOMMENDED_FRACTION * critical);
    assert_eq!(recommended, model.recommended_timestep(r, 0.5 * r, m, 0.3 * m));
}

#[test]
fn recommended_step_rejects_bad_bodies() {
    let model = BondModel::new(BondParams::default()).unwrap();
    let mut out = 0.0;
    let status = unsafe { granbond_bond_recommended_timestep(&model, 1e-3, 1e-3, -1.0, 1e-5, &mut out) };
    assert_eq!(status, Status::InvalidArgument);
    let status =
        unsafe { granbond_bond_recommended_timestep(std::ptr::null(), 1e-3, 1e-3, 1e-5, 1e-5, &mut out) };
    assert_eq!(status, Status::NullPointer);
}
