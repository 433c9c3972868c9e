//! Reference solutions (issue 4): the bond kernel in the scene runner against
//! closed forms, with tolerances taken from the measured convergence order.
//!
//! How each tolerance is set: the error `e(dt)` of a quantity computed with
//! symplectic Euler behaves like `C dt^p`. Each test measures `e` at `dt`,
//! `dt/2` (and `dt/4`), checks the measured order `p = log2(e(dt)/e(dt/2))`
//! against the expected one (a wrong order means a bug in the kernel, not
//! noise), then Richardson-extrapolates: `T_R = T(dt/2) + (T(dt/2) - T(dt)) /
//! (2^p - 1)` must match the closed form to a fraction of `e(dt/2)`. That
//! shows the numerical answer converges to the reference and not to
//! something near it. Step sizes are fractions of the core's critical-step
//! estimate `dt_c`.
//!
//! `cargo run --release -p granbond-scene --example study` measures the same quantities over
//! the whole range `1e-3 .. 1 dt_c` (docs/speed-accuracy.md).

use granbond::bond::section::section;
use granbond::bond::twist_bend::{BendHistory, TwistHistory};
use granbond::bond::{BondModel, BondParams, BondState};
use granbond::vector::Vec3;
use granbond_scene::reference::*;
use nalgebra::DVector;
use std::f64::consts::PI;

/// `delta_eps = 1e-3 rb`: the compression the unregularised estimate assumes.
const EPS: f64 = 5e-7;

fn critical(p: BondParams) -> f64 {
    let m = sphere_mass(RADIUS, DENSITY);
    BondModel::new(p).unwrap().critical_timestep(RADIUS, RADIUS, m, m)
}

fn order(coarse: f64, fine: f64) -> f64 {
    (coarse / fine).abs().log2()
}

/// Values of one quantity at `dt`, `dt/2`, `dt/4`: asserts that each halving
/// shrinks the error by `2^p` with `|p - 2| < order_tolerance`, and that the
/// Richardson extrapolation of the last two, `T_R = T(dt/4) + (T(dt/4) -
/// T(dt/2)) / 3`, is within `fraction` of the finest error of `exact`.
/// Returns the relative errors.
fn second_order(values: &[f64], exact: f64, order_tolerance: f64, fraction: f64) -> Vec<f64> {
    let e: Vec<f64> = values.iter().map(|v| v / exact - 1.0).collect();
    for w in e.windows(2) {
        let q = order(w[0], w[1]);
        assert!((q - 2.0).abs() < order_tolerance, "order {q}, errors {e:?}");
    }
    let (coarse, fine) = (values[values.len() - 2], values[values.len() - 1]);
    let r = (fine + (fine - coarse) / 3.0) / exact - 1.0;
    let last = e[e.len() - 1];
    assert!(r.abs() < fraction * last.abs(), "Richardson {r:e} vs e {last:e}");
    e
}

#[test]
fn linear_tension_oscillator_period_is_second_order_in_dt() {
    let p = study_bond(false);
    let osc = TensionOscillator::new(p);
    let exact = osc.period();
    let dt_c = critical(p);
    let dts = [0.2 * dt_c, 0.1 * dt_c, 0.05 * dt_c];
    let t: Vec<f64> = dts.iter().map(|&dt| osc.run(dt, 4).unwrap().value).collect();
    // Second order: e(dt/2) = e(dt)/4 up to 2^-2 of it (order within 0.1);
    // the extrapolation removes the dt^2 term and leaves the dt^4 one,
    // e(dt/2)^2 in size, far below 5% of e.
    let e = second_order(&t, exact, 0.1, 0.05);
    // Symplectic Euler on a linear oscillator is exactly x_n = A cos(w' n dt)
    // with sin(w' dt / 2) = w dt / 2: the period error is -(w dt)^2 / 24 + ...
    let omega = 2.0 * PI / exact;
    for (dt, err) in dts.iter().zip(&e) {
        let discrete = (0.5 * omega * dt) / (0.5 * omega * dt).asin() - 1.0;
        assert!(
            (err - discrete).abs() < 0.02 * discrete.abs(),
            "dt {dt:e}: {err:e} vs the discrete solution's {discrete:e}"
        );
    }
    // At 0.2 dt_c the period is already within 2e-3 (measured 1.9e-3).
    assert!(e[0].abs() < 2e-3);
}

#[test]
fn square_root_oscillator_period_matches_the_beta_function_closed_form() {
    // The constant B(2/3, 1/2) = int_0^1 u^(-1/3) (1-u)^(-1/2) du (the
    // derivation of the period is on `SqrtOscillator::period`). With
    // u = sin^2(phi) both end singularities go away:
    // B = 2 int_0^(pi/2) sin^(1/3)(phi) dphi; check the hard-coded value.
    let n = 200_000;
    let h = 0.5 * PI / n as f64;
    let beta: f64 = (0..n)
        .map(|k| 2.0 * ((k as f64 + 0.5) * h).sin().powf(1.0 / 3.0) * h)
        .sum();
    // Midpoint rule on the phi^(1/3) cusp at 0: error ~ h^(4/3), 2e-8 here.
    assert!((beta - BETA_2_3_HALF).abs() < 1e-7, "B(2/3,1/2) = {beta}");

    // Amplitude 0.04 rb: plain square root (delta_eps = 0), as in the spec.
    let p = study_bond(false);
    let osc = SqrtOscillator::new(p, 2e-5);
    let exact = osc.period();
    let dt_c = critical(p);
    let t: Vec<f64> = [0.1, 0.05, 0.025]
        .iter()
        .map(|f| osc.run(f * dt_c, 4).unwrap().value)
        .collect();
    // Measured: 1.2e-3, 3.1e-4, 7.3e-5 (orders 2.0 and 2.1). At coarser steps
    // the error is not monotonic: the stiffness is unbounded where the
    // sphere crosses x = 0, and the step that straddles it sees a force of
    // order c sqrt(v dt). Expected order 2 where it is asymptotic; allow
    // +-0.3 for that straddling step, whose error is not smooth in dt, and
    // a Richardson residue of a quarter of the finest error.
    second_order(&t, exact, 0.3, 0.25);
}

fn cantilever() -> Cantilever {
    Cantilever::new(
        BondParams {
            compression_linear_below: EPS,
            ..study_bond(false)
        },
        6,
    )
}

#[test]
fn cantilever_static_tip_deflection_against_euler_bernoulli_and_timoshenko() {
    let c = cantilever();
    let load = 1e-3;
    // The chain's stiffness matrix, assembled from the bond laws, gives the
    // closed form of `Cantilever::chain_tip` (to round-off).
    let (k, _) = c.stiffness_and_mass();
    let tip = k.nrows() - 2;
    let mut f = DVector::zeros(k.nrows());
    f[tip] = load;
    let u = k.lu().solve(&f).unwrap();
    let chain = c.chain_tip(load);
    assert!((u[tip] / chain - 1.0).abs() < 1e-9);

    // Model difference, derived: chain = EB (1 - (h/L)^2/4) + P L / (k_t A h),
    // so chain/EB - 1 = -(h/L)^2/4 + 3 EI / (k_t A h L^2) = -0.69% + 0.13%
    // for six bonds (EI = k_tt I h, kappa G A = k_t A h).
    let eb = c.euler_bernoulli_tip(load);
    let (h, l) = (c.bond_length(), c.length());
    let predicted = -(h / l).powi(2) / 4.0 + 3.0 * c.bending_rigidity() / (c.shear_rigidity() * l * l);
    assert!((chain / eb - 1.0 - predicted).abs() < 1e-12);
    assert!((chain / eb - 1.0).abs() < 1e-2);

    // The kernel in the scene, relaxed by kinetic damping at 0.1 dt_c: the
    // static answer does not depend on dt. Measured within 7e-4 of the
    // chain's closed form (the incremental shear spring follows the
    // relaxation path: it is projected, not rotated, onto the turning bond
    // axis); allow 2e-3.
    let dt = 0.1 * critical(c.params);
    let run = c.sag(dt, load, 100_000).unwrap();
    assert!(
        (run.value / chain - 1.0).abs() < 2e-3,
        "sag {:e} vs chain {chain:e}",
        run.value
    );
}

#[test]
fn cantilever_first_frequency_converges_to_the_chains_and_approaches_euler_bernoulli() {
    let c = cantilever();
    let (omega, _) = c.chain_mode();
    let dt_c = critical(c.params);
    let w: Vec<f64> = [0.4, 0.2, 0.1]
        .iter()
        .map(|f| c.ring(f * dt_c, 2).unwrap().value)
        .collect();
    // Measured 4.2e-7, 1.0e-7, 2.7e-8: second order (the mode is a linear
    // oscillator, the same -(w dt)^2/24 law, with w = w_1 << 2/dt).
    second_order(&w, omega, 0.2, 0.2);

    // Against Euler-Bernoulli the chain's lumped masses (a full sphere at the
    // tip where the beam has half an element), the spheres' rotary inertia
    // and the shear flexibility make it 14% low with 6 bonds, 7.8% with 12:
    // a model difference of order h/L that halves when the bonds double.
    let gap = |bonds| {
        let c = Cantilever::new(c.params, bonds);
        1.0 - c.chain_mode().0 / c.euler_bernoulli_frequency()
    };
    let (g6, g12, g24) = (gap(6), gap(12), gap(24));
    assert!(g6 > 0.0 && g6 < 0.16, "{g6}");
    for (a, b) in [(g6, g12), (g12, g24)] {
        assert!((a / b - 2.0).abs() < 0.25, "first order in h/L: {a} -> {b}");
    }
}

#[test]
fn undamped_free_cluster_keeps_its_energy_to_a_bound_that_shrinks_with_dt() {
    // Elastic bonds (ku = k, kc = 0), every degree of freedom, regularised
    // square root (delta_eps = 1e-3 rb, so dt_c covers it; without it the
    // energy is not conserved at small amplitudes: see stability_sweep.rs).
    let p = BondParams {
        compression_linear_below: EPS,
        ..study_bond(false)
    };
    let dt_c = critical(p);
    let span = 200.0 * dt_c;
    let e: Vec<f64> = [0.1, 0.05, 0.025]
        .iter()
        .map(|f| {
            let mut scene = free_cluster(p, f * dt_c, 3.0, 0.01, 1);
            energy_error(&mut scene, (span / (f * dt_c)) as u64)
                .unwrap()
                .value
        })
        .collect();
    // With the kinetic energy averaged across the step, the energy error of
    // symplectic Euler is second order (measured orders 1.9 and 1.9); the
    // initial velocities load the incremental shear spring and angles half a
    // step early, a first-order part that is small here. Expect between 1.5
    // and 2.3.
    for pair in e.windows(2) {
        let q = order(pair[0], pair[1]);
        assert!(q > 1.5 && q < 2.3, "order {q}, errors {e:?}");
    }
    assert!(e[0] < 2e-2, "{e:?}");
}

/// Trapezoidal integral of `f` over `[0, x]` with `n` panels.
fn integral(f: impl Fn(f64) -> f64, x: f64, n: usize) -> f64 {
    let h = x / n as f64;
    (0..n)
        .map(|k| 0.5 * (f(k as f64 * h) + f((k + 1) as f64 * h)) * h)
        .sum()
}

#[test]
fn elastic_energy_is_the_integral_of_each_law() {
    for eps in [0.0, 1e-6] {
        let p = BondParams {
            compression_linear_below: eps,
            ..study_bond(false)
        };
        let m = BondModel::new(p).unwrap();
        let sec = section(p.lambda, RADIUS, RADIUS);
        let normal = |d: f64| sec.area * m.normal.stress(d, d.max(0.0), d.min(0.0), true, true);
        let state = BondState::created(2.0 * RADIUS);
        for d in [3e-6, 5e-7, -2e-6] {
            // The work of the force from 0 to d (the force opposes d < 0 too).
            let work = integral(normal, d, 400_000).abs();
            let energy = m.elastic_energy(&state, d, RADIUS, RADIUS).total();
            assert!(
                (energy / work - 1.0).abs() < 1e-6,
                "eps {eps} d {d}: {energy} vs {work}"
            );
        }
    }
    // Shear, twisting and bending, through their own laws.
    let p = study_bond(false);
    let m = BondModel::new(p).unwrap();
    let sec = section(p.lambda, RADIUS, RADIUS);
    let slip = 1e-7;
    let shear = integral(|s| p.k_ft * sec.area * s, slip, 1000);
    let theta = 2e-3;
    // Virgin loading (fresh history) along an oblique axis, across it for
    // bending.
    let n = Vec3::new(0.3, -0.4, 0.866) * (1.0 / Vec3::new(0.3, -0.4, 0.866).norm());
    let across = Vec3::new(0.4, 0.3, 0.0) * (1.0 / 0.5);
    let twist = integral(
        |t| {
            let fresh = TwistHistory { max: 0.0, min: 0.0 };
            m.twist.twist(n * t, n, fresh, sec.polar).0.torque.norm()
        },
        theta,
        1000,
    );
    let bend = integral(
        |t| {
            let fresh = BendHistory {
                leading: Vec3::zeros(),
                opposite: 0.0,
            };
            m.bend.bend(across * t, n, fresh, sec.inertia).0.torque.norm()
        },
        theta,
        1000,
    );
    let state = BondState {
        shear_force: [p.k_ft * sec.area * slip, 0.0, 0.0],
        twist_angle: [theta, 0.0, 0.0],
        bend_angle: [0.0, theta, 0.0],
        ..BondState::created(2.0 * RADIUS)
    };
    let e = m.elastic_energy(&state, 0.0, RADIUS, RADIUS);
    for (got, want, what) in [
        (e.shear, shear, "shear"),
        (e.twist, twist, "twist"),
        (e.bend, bend, "bend"),
    ] {
        assert!((got / want - 1.0).abs() < 1e-9, "{what}: {got} vs {want}");
    }
}
