//! The Voigt contact against closed forms: restitution, contact time,
//! stick/slip at mu Fn, rolling at 5/7 v0, rolling resistance on rolling only.

use granbond_test_support as common;

use common::{DENSITY, RADIUS};
use granbond::contact::{ContactOutput, ContactState, Plane, VoigtModel, VoigtParams};
use granbond::kinematics::PairKinematics;
use granbond::vector::{v3, Vec3};
use granbond_scene::{Scene, Sphere};

fn voigt(p: VoigtParams) -> VoigtModel {
    VoigtModel::new(p).expect("valid parameters")
}

/// Head-on collision of two equal spheres: (restitution, contact time).
fn collide(p: VoigtParams, dt: f64) -> (f64, f64) {
    let mut scene = Scene::new(dt);
    let mut a = Sphere::new(Vec3::zeros(), RADIUS, DENSITY);
    let mut b = Sphere::new(Vec3::new(2.0 * RADIUS + 1e-9, 0.0, 0.0), RADIUS, DENSITY);
    a.body.v = Vec3::new(0.05, 0.0, 0.0);
    b.body.v = Vec3::new(-0.05, 0.0, 0.0);
    scene.spheres = vec![a, b];
    scene.contact_model = Some(voigt(p));
    let mut steps_in_contact = 0usize;
    let mut started = false;
    loop {
        let report = scene.advance().unwrap();
        if report.contacts > 0 {
            started = true;
            steps_in_contact += 1;
        } else if started {
            break;
        }
        assert!(scene.step < 10_000_000);
    }
    let v_after = scene.spheres[1].body.v.x - scene.spheres[0].body.v.x;
    (v_after / 0.1, steps_in_contact as f64 * dt)
}

#[test]
fn restitution_and_contact_time_match_the_closed_forms() {
    let m = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let m_eff = m / 2.0;
    for gamma_n in [1e-3, 5e-2] {
        let p = VoigtParams {
            gamma_n,
            no_attraction: 0,
            rolling: 0,
            ..VoigtParams::default()
        };
        let zeta = gamma_n / (2.0 * (p.k_n * m_eff).sqrt());
        let e = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        let t_c = std::f64::consts::PI / (p.k_n / m_eff - (gamma_n / (2.0 * m_eff)).powi(2)).sqrt();
        let dt = t_c / 4000.0;
        let (e_num, t_num) = collide(p, dt);
        // Symplectic Euler: errors of order dt/t_c = 2.5e-4.
        assert!((e_num - e).abs() < 2e-3 * e, "zeta={zeta}: e {e_num} vs {e}");
        assert!(
            (t_num - t_c).abs() < 1e-3 * t_c,
            "zeta={zeta}: t_c {t_num} vs {t_c}"
        );
    }
}

#[test]
fn tangential_force_sticks_below_and_slides_at_mu_fn() {
    let p = VoigtParams {
        rolling: 0,
        ..VoigtParams::default()
    };
    let model = voigt(p);
    let overlap = 1e-6;
    let slip = 0.01;
    let dt = 1e-7;
    let kin = PairKinematics {
        x_i: [2.0 * RADIUS - overlap, 0.0, 0.0],
        v_i: [0.0, slip, 0.0],
        radius_i: RADIUS,
        radius_j: RADIUS,
        ..PairKinematics::default()
    };
    let f_n = p.k_n * overlap;
    let mut state = ContactState::default();
    let mut slid_at = None;
    for k in 1..=2000 {
        let mut out = ContactOutput::default();
        model.step(&kin, dt, &mut state, &mut out).unwrap();
        let f_t = out.force_i[1];
        assert!(f_t < 0.0, "friction opposes the slip (the seed's sign would not)");
        assert!(f_t.abs() <= p.mu * f_n * (1.0 + 1e-12));
        let trial = p.k_t * slip * dt * k as f64 + p.gamma_t * slip;
        if slid_at.is_none() {
            assert_eq!(out.sliding == 1, trial > p.mu * f_n, "step {k}");
            if out.sliding == 1 {
                slid_at = Some(k);
            } else {
                assert!((f_t + trial).abs() < 1e-12 * trial, "stick: Ft = -(kt xi + gt v)");
            }
        } else {
            assert_eq!(out.sliding, 1);
            assert!((f_t.abs() - p.mu * f_n).abs() < 1e-12 * f_n);
        }
    }
    assert!(slid_at.is_some());
    // While sliding the spring stays consistent with the cap.
    let consistent = (p.mu * f_n - p.gamma_t * slip) / p.k_t;
    assert!((v3(state.tangential_spring).norm() - consistent).abs() < 1e-12 * consistent);
}

#[test]
fn a_sliding_sphere_ends_rolling_at_five_sevenths_of_its_speed() {
    let p = VoigtParams {
        rolling: 0,
        ..VoigtParams::default()
    };
    let mut scene = Scene::new(1e-6);
    let mass = Sphere::new(Vec3::zeros(), RADIUS, DENSITY).body.mass;
    let rest = mass * 9.81 / p.k_n;
    let mut s = Sphere::new(Vec3::new(0.0, 0.0, RADIUS - rest), RADIUS, DENSITY);
    let v0 = 0.2;
    s.body.v = Vec3::new(v0, 0.0, 0.0);
    scene.spheres = vec![s];
    scene.planes = vec![Plane {
        point: [0.0; 3],
        normal: [0.0, 0.0, 1.0],
        velocity: [0.0; 3],
    }];
    scene.gravity = Vec3::new(0.0, 0.0, -9.81);
    scene.contact_model = Some(voigt(p));
    // Rolling starts after 2 v0 / (7 mu g) = 11.7 ms.
    for _ in 0..20_000 {
        scene.advance().unwrap();
    }
    let body = scene.spheres[0].body;
    assert!(
        (body.v.x - 5.0 / 7.0 * v0).abs() < 2e-3 * v0,
        "v = {} vs 5/7 v0 = {}",
        body.v.x,
        5.0 / 7.0 * v0
    );
    assert!(
        (body.w.y * RADIUS - body.v.x).abs() < 2e-3 * v0,
        "rolls without slip"
    );
}

fn touching(w_i: [f64; 3]) -> PairKinematics {
    PairKinematics {
        x_i: [2.0 * RADIUS - 1e-6, 0.0, 0.0],
        w_i,
        radius_i: RADIUS,
        radius_j: RADIUS,
        ..PairKinematics::default()
    }
}

#[test]
fn a_pure_spin_about_the_normal_meets_no_rolling_torque() {
    let model = voigt(VoigtParams {
        k_r: 1e-3,
        gamma_r: 1e-6,
        eta_r: 1e-6,
        ..VoigtParams::default()
    });
    let mut out = ContactOutput::default();
    let mut state = ContactState::default();
    model
        .step(&touching([50.0, 0.0, 0.0]), 1e-6, &mut state, &mut out)
        .unwrap();
    assert_eq!(out.torque_i, [0.0; 3]);
    assert_eq!(state.rolling_angle, [0.0; 3]);
    // The same spin across the normal is resisted.
    model
        .step(
            &touching([0.0, 50.0, 0.0]),
            1e-6,
            &mut ContactState::default(),
            &mut out,
        )
        .unwrap();
    assert!(out.torque_i[1] < 0.0);
}

#[test]
fn rolling_torque_is_capped_at_mu_r_fn_r_star_plus_the_viscous_term() {
    // No tangential spring or friction: the torques are the rolling ones.
    let p = VoigtParams {
        k_r: 1e-2,
        eta_r: 2e-8,
        k_t: 0.0,
        gamma_t: 0.0,
        mu: 0.0,
        ..VoigtParams::default()
    };
    let model = voigt(p);
    let spin = 30.0;
    let kin = touching([0.0, 0.0, spin]);
    let f_n = p.k_n * 1e-6;
    let cap = p.mu_r * f_n * RADIUS / 2.0;
    let mut state = ContactState::default();
    let mut capped = false;
    for _ in 0..200 {
        let mut out = ContactOutput::default();
        model.step(&kin, 1e-5, &mut state, &mut out).unwrap();
        assert_eq!(
            v3(out.torque_i),
            -v3(out.torque_j),
            "equal and opposite rolling torques"
        );
        let spring_part = out.torque_i[2] + p.eta_r * spin;
        assert!(spring_part.abs() <= cap * (1.0 + 1e-12));
        capped |= out.rolling_slip == 1;
    }
    assert!(capped, "the rolling spring reached its cap");
}

/// The evaluation a setup pass makes (`evaluate_frame`) gives, in the frame
/// and with the velocities of the last step, the loads that step applied,
/// bit for bit (no dashpots, below the caps), and leaves the state alone.
#[test]
fn evaluating_the_stored_state_gives_the_loads_of_the_last_step() {
    let p = VoigtParams {
        gamma_n: 0.0,
        gamma_t: 0.0,
        gamma_r: 0.0,
        eta_r: 0.0,
        rolling: 1,
        ..VoigtParams::default()
    };
    let m = voigt(p);
    // a normal off the axes, so that turning the stored spring into the
    // plane again would change its last bits
    let mut k = touching([3.0, -7.0, 30.0]);
    let r = 2.0 * RADIUS - 1e-6;
    k.x_i = [0.8 * r, 0.36 * r, 0.48 * r];
    k.v_j = [0.013, 0.05, 0.01];
    let mut state = ContactState::default();
    let mut last = ContactOutput::default();
    for _ in 0..50 {
        m.step(&k, 1e-7, &mut state, &mut last).unwrap();
    }
    assert!(last.force_i[1] != 0.0 && last.torque_i[1] != 0.0, "{last:?}");
    let kept = state;
    let frame = granbond::contact::sphere_sphere(&k).unwrap();
    let mut again = ContactOutput::default();
    m.evaluate_frame(&frame, &state, &mut again);
    assert_eq!(again, last);
    assert_eq!(state, kept);
    // a step instead adds one more spring increment
    let mut stepped = ContactOutput::default();
    m.step(&k, 1e-7, &mut state, &mut stepped).unwrap();
    assert_ne!(stepped.force_i, last.force_i);
}
