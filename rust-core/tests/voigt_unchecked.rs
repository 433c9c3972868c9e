//! The unchecked per-contact entries give the same bits as the checked
//! calls for the same contact, over many steps of sticking, sliding and
//! rolling contacts of pairs and walls; a non-finite result is still
//! reported, and coincident centres are named.

use granbond_test_support as common;

use common::{Numbers, RADIUS};
use granbond::contact::{
    sphere_plane, ContactFrame, ContactOutput, ContactState, Plane, VoigtModel, VoigtParams,
    CONTACT_STATE_LEN,
};
use granbond::ffi::contact::granbond_voigt_compute;
use granbond::ffi::contact_geometry::{
    granbond_contact_frame_separation, granbond_voigt_compute_normal_unchecked,
    granbond_voigt_compute_separation_unchecked,
};
use granbond::ffi::error::granbond_last_error_message;
use granbond::ffi::Status;
use granbond::kinematics::{PairKinematics, SphereKinematics};
use granbond::vector::v3;
use std::ffi::CStr;

const DT: f64 = 1e-7;

/// The separation entry on the pair `k`, as LAMMPS hands it over.
///
/// # Safety
/// `state` must hold `CONTACT_STATE_LEN` doubles.
unsafe fn separation_unchecked(
    model: &VoigtModel,
    k: &PairKinematics,
    dt: f64,
    state: *mut f64,
    out: &mut ContactOutput,
) -> Status {
    let del = [k.x_i[0] - k.x_j[0], k.x_i[1] - k.x_j[1], k.x_i[2] - k.x_j[2]];
    let rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    granbond_voigt_compute_separation_unchecked(
        model,
        del.as_ptr(),
        rsq,
        k.radius_i,
        k.radius_j,
        k.v_i.as_ptr(),
        k.v_j.as_ptr(),
        k.w_i.as_ptr(),
        k.w_j.as_ptr(),
        dt,
        state,
        out,
    )
}

/// The normal entry on the geometry and velocities of `frame`.
///
/// # Safety
/// `state` must hold `CONTACT_STATE_LEN` doubles.
unsafe fn normal_unchecked(
    model: &VoigtModel,
    frame: &ContactFrame,
    dt: f64,
    state: *mut f64,
    out: &mut ContactOutput,
) -> Status {
    granbond_voigt_compute_normal_unchecked(
        model,
        frame.n.as_ptr(),
        frame.lever_i + frame.lever_j - frame.overlap,
        frame.lever_i,
        frame.lever_j,
        frame.v_i.as_ptr(),
        frame.v_j.as_ptr(),
        frame.w_i.as_ptr(),
        frame.w_j.as_ptr(),
        dt,
        state,
        out,
    )
}

fn models() -> Vec<VoigtModel> {
    [0, 1]
        .iter()
        .flat_map(|&rolling| {
            [0, 1].map(|no_attraction| {
                VoigtModel::new(VoigtParams {
                    rolling,
                    no_attraction,
                    mu: 0.3,
                    mu_r: 0.02,
                    ..VoigtParams::default()
                })
                .unwrap()
            })
        })
        .collect()
}

fn assert_same(a: &ContactOutput, b: &ContactOutput, sa: &[f64], sb: &[f64], what: &str) {
    // bitwise: PartialEq on f64 would let -0.0 == 0.0 through
    let bits = |o: &ContactOutput| {
        let mut v: Vec<u64> = o
            .force_i
            .iter()
            .chain(&o.torque_i)
            .chain(&o.torque_j)
            .map(|x| x.to_bits())
            .collect();
        v.extend([o.normal_force.to_bits(), o.overlap.to_bits()]);
        v.extend([o.touching, o.sliding, o.rolling_slip].map(|x| x as u64));
        v
    };
    assert_eq!(bits(a), bits(b), "{what}: outputs differ");
    let sbits = |s: &[f64]| s.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(sbits(sa), sbits(sb), "{what}: states differ");
}

#[test]
fn pair_contacts_give_the_bits_of_granbond_voigt_compute() {
    let mut r = Numbers(7);
    let mut touching = 0;
    for (m, model) in models().iter().enumerate() {
        for contact in 0..50 {
            let (mut sa, mut sb) = ([0.0; CONTACT_STATE_LEN], [0.0; CONTACT_STATE_LEN]);
            let d = r.vec(1.0);
            let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let gap = 2.0 * RADIUS * (1.0 - 2e-4 * (r.uniform() + 0.5));
            let mut k = PairKinematics {
                x_i: d.map(|c| c / len * gap),
                x_j: [0.0; 3],
                v_i: r.vec(0.05),
                v_j: r.vec(0.05),
                w_i: r.vec(50.0),
                w_j: r.vec(50.0),
                radius_i: RADIUS * (1.0 + 0.3 * r.uniform()),
                radius_j: RADIUS,
            };
            for step in 0..200 {
                let (mut a, mut b) = (ContactOutput::default(), ContactOutput::default());
                unsafe {
                    assert_eq!(
                        granbond_voigt_compute(model, &k, DT, sa.as_mut_ptr(), &mut a),
                        Status::Ok
                    );
                    let status = separation_unchecked(model, &k, DT, sb.as_mut_ptr(), &mut b);
                    assert_eq!(status, Status::Ok);
                }
                assert_same(
                    &a,
                    &b,
                    &sa,
                    &sb,
                    &format!("model {m} contact {contact} step {step}"),
                );
                touching += a.touching;
                for c in 0..3 {
                    k.x_i[c] += k.v_i[c] * DT * 100.0;
                    k.v_i[c] += a.force_i[c] * 1e-3;
                    k.w_i[c] += a.torque_i[c] * 1e3;
                }
            }
        }
    }
    assert!(
        touching > 10_000,
        "the contacts hardly touched ({touching} steps)"
    );
}

/// A wall as the LIGGGHTS adapter hands it over: its normal, the centre's
/// distance from it, and radius 0.
#[test]
fn wall_contacts_through_the_normal_entry_give_the_bits_of_a_sphere_on_a_plane() {
    let mut r = Numbers(11);
    for (m, model) in models().iter().enumerate() {
        for contact in 0..50 {
            let (mut sa, mut sb) = ([0.0; CONTACT_STATE_LEN], [0.0; CONTACT_STATE_LEN]);
            let n = r.vec(1.0);
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let normal = n.map(|c| c / len);
            let depth = RADIUS * (1.0 - 1e-4 * (r.uniform() + 0.5));
            let sphere = SphereKinematics {
                x: normal.map(|c| c * depth),
                v: r.vec(0.05),
                w: r.vec(50.0),
                radius: RADIUS,
            };
            let plane = Plane {
                point: [0.0; 3],
                normal,
                velocity: r.vec(0.01),
            };
            for step in 0..100 {
                let (mut a, mut b) = (ContactOutput::default(), ContactOutput::default());
                model.step_frame(
                    &sphere_plane(&sphere, &plane),
                    DT,
                    ContactState::from_slots_mut(&mut sa),
                    &mut a,
                );
                // the centre's distance from the wall through the origin, as `sphere_plane` takes it
                let distance = v3(sphere.x).dot(&v3(normal));
                let status = unsafe {
                    granbond_voigt_compute_normal_unchecked(
                        model,
                        normal.as_ptr(),
                        distance,
                        RADIUS,
                        0.0,
                        sphere.v.as_ptr(),
                        plane.velocity.as_ptr(),
                        sphere.w.as_ptr(),
                        [0.0; 3].as_ptr(),
                        DT,
                        sb.as_mut_ptr(),
                        &mut b,
                    )
                };
                assert_eq!(status, Status::Ok);
                assert_same(
                    &a,
                    &b,
                    &sa,
                    &sb,
                    &format!("model {m} wall contact {contact} step {step}"),
                );
            }
        }
    }
}

#[test]
fn a_non_finite_result_is_reported() {
    let model = &models()[3];
    let mut frame = ContactFrame {
        n: [1.0, 0.0, 0.0],
        overlap: 1e-6,
        lever_i: RADIUS,
        lever_j: RADIUS,
        r_eff: RADIUS / 2.0,
        ..ContactFrame::default()
    };
    let mut state = [0.0; CONTACT_STATE_LEN];
    let mut out = ContactOutput::default();
    unsafe {
        let ok = normal_unchecked(model, &frame, DT, state.as_mut_ptr(), &mut out);
        assert_eq!(ok, Status::Ok);
        assert!(out.force_i[0] > 0.0);
        for bad in [f64::NAN, f64::INFINITY] {
            frame.v_i[1] = bad;
            let status = normal_unchecked(model, &frame, DT, state.as_mut_ptr(), &mut out);
            assert_eq!(status, Status::NonFiniteResult, "v_i = {bad}");
            let message = CStr::from_ptr(granbond_last_error_message())
                .to_string_lossy()
                .into_owned();
            assert!(
                message.contains("granbond_voigt_compute_normal_unchecked"),
                "{message}"
            );
        }
    }
}

#[test]
fn coincident_centres_are_named_as_such() {
    let model = &models()[3];
    let (del, zero) = ([0.0; 3], [0.0; 3]);
    let mut state = [0.0; CONTACT_STATE_LEN];
    let mut out = ContactOutput::default();
    let mut frame = ContactFrame::default();
    let last = || unsafe {
        CStr::from_ptr(granbond_last_error_message())
            .to_string_lossy()
            .into_owned()
    };
    unsafe {
        let status = granbond_voigt_compute_separation_unchecked(
            model,
            del.as_ptr(),
            0.0,
            RADIUS,
            RADIUS,
            zero.as_ptr(),
            zero.as_ptr(),
            zero.as_ptr(),
            zero.as_ptr(),
            DT,
            state.as_mut_ptr(),
            &mut out,
        );
        assert_eq!(status, Status::CoincidentCentres);
        assert!(last().contains("coincident centres"), "{}", last());
        let status = granbond_contact_frame_separation(
            del.as_ptr(),
            0.0,
            RADIUS,
            RADIUS,
            zero.as_ptr(),
            zero.as_ptr(),
            zero.as_ptr(),
            zero.as_ptr(),
            &mut frame,
        );
        assert_eq!(status, Status::CoincidentCentres);
        assert!(last().contains("coincident centres"), "{}", last());
    }
}
