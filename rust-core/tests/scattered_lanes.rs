//! `BondModel::step_batch` and `BondModel::step_scattered` compute bonds several at a time (in lanes of
//! 4 with AVX2); every bond must still get exactly the bits one
//! `BondModel::step` gives it, whichever lane or chunk it lands in, and on
//! every instruction set, including bonds that are not intact, break in
//! this step, sit at the zero-angle / zero-slip guards, or have unusable
//! kinematics (the first one reported with its index, earlier bonds
//! computed, later ones untouched). `BondModel::step_indexed`, which reads
//! the kinematics from per-atom arrays by index, must give the same bits.

use granbond_test_support as common;

use common::strategies::{bond_params, bonded_pair};
use granbond::bond::features::{BEND, COMPILED_ALONE, COMPRESSION, DAMPING, SHEAR, SMOOTH, TENSION, TWIST};
use granbond::bond::finite::{bond_finite, BatchResult};
use granbond::bond::{BondModel, BondOutput, BondParams, BondState, BondStatus, Simd};
use granbond::kinematics::{KinematicsError, PairKinematics};
use granbond::pair_source::{AtomArrays, IndexedPairs};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

const DT: f64 = 1e-7;
const EVERY_SIMD: [Simd; 3] = [Simd::Scalar, Simd::Avx2, Simd::Avx512];

/// What sets a bond apart from the plain bonded pair of `bonded_pair`.
#[derive(Clone, Copy, Debug)]
enum Twist {
    Plain,
    Broken,
    Unbonded,
    /// Fresh history, no motion: zero angles, zero slip, zero spin.
    AtRest,
    /// Stretched by 50 %: breaks in distance mode with a small limit.
    FarApart,
    NonFinite,
    Coincident,
    NonPositiveRadius,
}

fn twist() -> impl Strategy<Value = Twist> {
    prop_oneof![
        12 => Just(Twist::Plain),
        2 => Just(Twist::Broken),
        2 => Just(Twist::Unbonded),
        3 => Just(Twist::AtRest),
        3 => Just(Twist::FarApart),
        1 => Just(Twist::NonFinite),
        1 => Just(Twist::Coincident),
        1 => Just(Twist::NonPositiveRadius),
    ]
}

fn bond() -> impl Strategy<Value = (PairKinematics, BondState)> {
    (bonded_pair(), twist()).prop_map(|((mut k, mut s), t)| {
        match t {
            Twist::Plain => {}
            Twist::Broken => s.mark_broken(),
            Twist::Unbonded => s = BondState::default(),
            Twist::AtRest => {
                s = BondState::created(s.r0());
                (k.v_i, k.v_j, k.w_i, k.w_j) = ([0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3]);
            }
            Twist::FarApart => k.x_i = k.x_i.map(|x| 1.5 * x),
            Twist::NonFinite => k.w_j[1] = f64::NAN,
            Twist::Coincident => k.x_i = k.x_j,
            Twist::NonPositiveRadius => k.radius_j = 0.0,
        }
        (k, s)
    })
}

/// Every switch at random (all 128 combinations), distance or stress mode with
/// limits that some bonds exceed, the linear continuation of the
/// compression law on or off.
fn any_params() -> impl Strategy<Value = BondParams> {
    (
        bond_params(),
        prop::array::uniform8(any::<bool>()),
        (2.5e-3f64..5e-3),
        (1.0f64..10.0),
        (1.0f64..10.0),
        prop_oneof![Just(0.0), 1e-7f64..1e-5],
    )
        .prop_map(|(p, on, max_distance, sigma, tau, linear_below)| BondParams {
            tension: on[0] as i32,
            compression: on[1] as i32,
            shear: on[2] as i32,
            twist: on[3] as i32,
            bend: on[4] as i32,
            stress_break: on[5] as i32,
            history_reset: on[6] as i32,
            use_ratio: on[7] as i32,
            tension_compression_ratio: 0.5,
            max_distance,
            max_sigma: 10f64.powf(sigma),
            max_tau: 10f64.powf(tau),
            compression_linear_below: linear_below,
            ..p
        })
}

/// One bond after another with `BondModel::step`, stopping at the first
/// error and naming the first bond whose results are not finite: what
/// `step_scattered` must reproduce.
fn one_by_one(
    m: &BondModel,
    kin: &[PairKinematics],
    states: &mut [BondState],
    outs: &mut [BondOutput],
) -> Result<Option<usize>, (usize, KinematicsError)> {
    let mut first = None;
    for (i, k) in kin.iter().enumerate() {
        m.step(k, DT, &mut states[i], &mut outs[i]).map_err(|e| (i, e))?;
        if first.is_none() && !bond_finite(&states[i], &outs[i]) {
            first = Some(i);
        }
    }
    Ok(first)
}

fn output_bits(o: &BondOutput) -> Vec<u64> {
    let mut bits: Vec<u64> = o
        .force_i
        .iter()
        .chain(&o.torque_i)
        .chain(&o.torque_j)
        .chain(&[o.normal_force, o.sigma, o.tau, o.delta])
        .map(|x| x.to_bits())
        .collect();
    bits.extend([o.status as u64, o.break_mode as u64]);
    bits
}

fn state_bits(s: &BondState) -> Vec<u64> {
    s.as_slots().iter().map(|x| x.to_bits()).collect()
}

/// Outputs that a bond left untouched would show: not a possible result.
fn stale_outputs(n: usize) -> Vec<BondOutput> {
    let stale = BondOutput {
        force_i: [7.0; 3],
        sigma: -3.0,
        status: 9,
        break_mode: 9,
        ..BondOutput::default()
    };
    vec![stale; n]
}

/// Per-atom arrays holding the two spheres of every bond, and the index
/// pairs that find them again: bond `b` joins atoms `2n - 1 - b` (its `i`)
/// and `b` (its `j`), so neighbouring bonds read atoms far apart and no
/// bond's `i` comes before its `j`.
struct Atoms {
    x: Vec<f64>,
    v: Vec<f64>,
    omega: Vec<f64>,
    radius: Vec<f64>,
    pairs: Vec<[i32; 2]>,
}

impl Atoms {
    fn of(kin: &[PairKinematics]) -> Self {
        let n = kin.len();
        let mut a = Atoms {
            x: vec![f64::NAN; 6 * n],
            v: vec![f64::NAN; 6 * n],
            omega: vec![f64::NAN; 6 * n],
            radius: vec![f64::NAN; 2 * n],
            pairs: Vec::with_capacity(n),
        };
        for (b, k) in kin.iter().enumerate() {
            let (i, j) = (2 * n - 1 - b, b);
            for (atom, x, v, w, r) in [
                (i, k.x_i, k.v_i, k.w_i, k.radius_i),
                (j, k.x_j, k.v_j, k.w_j, k.radius_j),
            ] {
                a.x[3 * atom..3 * atom + 3].copy_from_slice(&x);
                a.v[3 * atom..3 * atom + 3].copy_from_slice(&v);
                a.omega[3 * atom..3 * atom + 3].copy_from_slice(&w);
                a.radius[atom] = r;
            }
            a.pairs.push([i as i32, j as i32]);
        }
        a
    }

    fn arrays(&self) -> AtomArrays<'_> {
        AtomArrays {
            x: &self.x,
            v: &self.v,
            omega: &self.omega,
            radius: &self.radius,
        }
    }
}

const SOURCES: [&str; 3] = ["batch", "scattered", "indexed"];

/// `bonds` through `step_batch` (states side by side), `step_scattered` or
/// `step_indexed` of `m`: the result, the states and the outputs.
fn run(
    m: &BondModel,
    source: &str,
    kin: &[PairKinematics],
    indexed: &IndexedPairs<'_>,
    bonds: &[(PairKinematics, BondState)],
) -> (BatchResult, Vec<BondState>, Vec<BondOutput>) {
    let mut states: Vec<BondState> = bonds.iter().map(|b| b.1).collect();
    let mut outs = stale_outputs(bonds.len());
    let got = if source == "batch" {
        m.step_batch(kin, DT, &mut states, &mut outs)
    } else {
        let mut refs: Vec<&mut BondState> = states.iter_mut().collect();
        match source {
            "scattered" => m.step_scattered(kin, DT, &mut refs, &mut outs),
            _ => m.step_indexed(indexed, DT, &mut refs, &mut outs),
        }
    };
    (got, states, outs)
}

/// `step_batch` (states side by side), `step_scattered` and `step_indexed`
/// on every instruction set this CPU runs against one `step` per bond, bit
/// for bit. Returns how many
/// instruction sets ran.
fn check_scattered(p: BondParams, bonds: &[(PairKinematics, BondState)]) -> Result<usize, TestCaseError> {
    let model = BondModel::new(p).unwrap();
    let kin: Vec<PairKinematics> = bonds.iter().map(|b| b.0).collect();
    let atoms = Atoms::of(&kin);
    let indexed = IndexedPairs::new(atoms.arrays(), &atoms.pairs).unwrap();
    let mut expected_states: Vec<BondState> = bonds.iter().map(|b| b.1).collect();
    let mut expected_outs = stale_outputs(bonds.len());
    let expected = one_by_one(&model, &kin, &mut expected_states, &mut expected_outs);
    let mut ran = 0;
    for simd in EVERY_SIMD {
        let Some(m) = model.clone().with_simd(simd) else {
            continue;
        };
        ran += 1;
        for source in SOURCES {
            let (got, states, outs) = run(&m, source, &kin, &indexed, bonds);
            prop_assert_eq!(got, expected, "{:?} {}: result", simd, source);
            for i in 0..bonds.len() {
                prop_assert_eq!(
                    state_bits(&states[i]),
                    state_bits(&expected_states[i]),
                    "{:?} {}: state of bond {} of {}",
                    simd,
                    source,
                    i,
                    bonds.len()
                );
                prop_assert_eq!(
                    output_bits(&outs[i]),
                    output_bits(&expected_outs[i]),
                    "{:?} {}: output of bond {} of {}",
                    simd,
                    source,
                    i,
                    bonds.len()
                );
            }
        }
    }
    Ok(ran)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn scattered_step_gives_every_bond_the_bits_of_a_single_step(
        p in any_params(),
        bonds in prop::collection::vec(bond(), 0..=20),
    ) {
        check_scattered(p, &bonds)?;
    }
}

/// 20 bonds and a parameter set, drawn once, the same in every run.
fn twenty_bonds_and_params() -> (Vec<(PairKinematics, BondState)>, BondParams) {
    let mut runner = TestRunner::deterministic();
    let bonds = prop::collection::vec(bond(), 20)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let base = any_params().new_tree(&mut runner).unwrap().current();
    (bonds, base)
}

/// Each of the 128 combinations of switches, in both breakage modes, on the
/// same 20 bonds drawn once.
#[test]
fn every_kernel_gives_every_bond_the_bits_of_a_single_step() {
    let (bonds, base) = twenty_bonds_and_params();
    for features in 0..128u32 {
        for stress_break in [0, 1] {
            let on = |bit: u32| (features >> bit & 1) as i32;
            let p = BondParams {
                tension: on(0),
                compression: on(1),
                shear: on(2),
                twist: on(3),
                bend: on(4),
                damping: on(5),
                damping_smooth: on(6),
                eta_fn: 0.3,
                stress_break,
                ..base
            };
            check_scattered(p, &bonds).unwrap();
        }
    }
}

/// Every step of `m` this CPU runs (one bond at a time, and `step_batch`,
/// `step_scattered`, `step_indexed` on each instruction set) on `bonds`:
/// the result, the states' and the outputs' bits.
fn every_step(
    m: &BondModel,
    bonds: &[(PairKinematics, BondState)],
) -> Vec<(String, BatchResult, Vec<Vec<u64>>)> {
    let kin: Vec<PairKinematics> = bonds.iter().map(|b| b.0).collect();
    let atoms = Atoms::of(&kin);
    let indexed = IndexedPairs::new(atoms.arrays(), &atoms.pairs).unwrap();
    let mut runs = Vec::new();
    let mut record = |name: String, got: BatchResult, states: &[BondState], outs: &[BondOutput]| {
        let bits = states
            .iter()
            .map(state_bits)
            .chain(outs.iter().map(output_bits))
            .collect();
        runs.push((name, got, bits));
    };
    let mut states: Vec<BondState> = bonds.iter().map(|b| b.1).collect();
    let mut outs = stale_outputs(bonds.len());
    let got = one_by_one(m, &kin, &mut states, &mut outs);
    record("step".into(), got, &states, &outs);
    for simd in EVERY_SIMD {
        let Some(m) = m.clone().with_simd(simd) else {
            continue;
        };
        for source in SOURCES {
            let (got, states, outs) = run(&m, source, &kin, &indexed, bonds);
            record(format!("{simd:?} {source}"), got, &states, &outs);
        }
    }
    runs
}

/// `base` with the switches of the `features` bits, and a damping ratio
/// that makes the damping bit count.
fn switched_on(features: u32, base: BondParams) -> BondParams {
    let on = |bit: u32| (features & bit != 0) as i32;
    BondParams {
        tension: on(TENSION),
        compression: on(COMPRESSION),
        shear: on(SHEAR),
        twist: on(TWIST),
        bend: on(BEND),
        damping: on(DAMPING),
        damping_smooth: on(SMOOTH),
        eta_fn: 0.3,
        ..base
    }
}

/// The combinations decks use have steps compiled for them alone (on AVX2
/// where the CPU has it), and those give every bond the bits of the steps
/// that read the switches at run time, in both breakage modes.
#[test]
fn common_switch_sets_run_an_avx2_step_of_their_own_with_the_same_bits() {
    let mut runner = TestRunner::deterministic();
    let bonds = prop::collection::vec(bond(), 23)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let base = any_params().new_tree(&mut runner).unwrap().current();
    for features in COMPILED_ALONE {
        for stress_break in [0, 1] {
            let p = BondParams {
                // above the bonds' speeds, so that smoothing changes the
                // damping
                smooth_velocity: 1e2,
                smooth_angular_velocity: 1e4,
                stress_break,
                ..switched_on(features, base)
            };
            let own = BondModel::new(p).unwrap();
            assert_eq!(own.features, features);
            assert!(own.compiled_alone(), "{features}: a step of its own");
            #[cfg(target_arch = "x86_64")]
            if is_x86_feature_detected!("avx2") {
                let avx2 = own.clone().with_simd(Simd::Avx2).unwrap();
                assert!(avx2.compiled_alone(), "{features}: an AVX2 step of its own");
            }
            let switched = own.clone().switched();
            assert!(!switched.compiled_alone());
            let (mine, theirs) = (every_step(&own, &bonds), every_step(&switched, &bonds));
            assert_eq!(mine.len(), theirs.len());
            for (a, b) in mine.iter().zip(&theirs) {
                assert_eq!(a.0, b.0);
                assert_eq!(a.1, b.1, "{features} {}: result", a.0);
                assert!(a.2 == b.2, "{features} {}: bits", a.0);
            }
        }
    }
}

/// Results that are not finite are found in every lane: with the history
/// extremes of bonds `k` and `k + 5` near the largest double (finite, but
/// their sum overflows), each batch names bond `k`, as one step per bond
/// and the rule of `bond_finite` do, and advances every bond.
#[test]
fn every_kernel_names_the_first_bond_whose_results_are_not_finite() {
    let mut runner = TestRunner::deterministic();
    let p = BondParams {
        twist: 1,
        bend: 1,
        ..any_params().new_tree(&mut runner).unwrap().current()
    };
    names_the_first_bond_not_finite(p, &mut runner);
}

/// The slots of the laws switched off count in the results check like the
/// others: every common set of switches (twist and bend off in most) names
/// bond `k` too, in lanes as one step per bond does.
#[test]
fn slots_of_switched_off_laws_count_in_the_results_check() {
    let mut runner = TestRunner::deterministic();
    let base = any_params().new_tree(&mut runner).unwrap().current();
    for features in COMPILED_ALONE {
        names_the_first_bond_not_finite(switched_on(features, base), &mut runner);
    }
}

/// With the history extremes of bonds `k` and `k + 5` near the largest
/// double (finite, but their sum overflows), each batch of a model with
/// parameters `p` names bond `k`, as one step per bond and the rule of
/// `bond_finite` do, and advances every bond.
fn names_the_first_bond_not_finite(p: BondParams, runner: &mut TestRunner) {
    let model = BondModel::new(p).unwrap();
    let good = good_bonds(&model, runner);
    for k in 0..12 {
        let mut bonds = good.clone();
        for b in [k, k + 5] {
            let state = &mut bonds[b].1;
            state.twist_max = 1.7e308;
            state.bend_opposite = 1.7e308;
        }
        let kin: Vec<PairKinematics> = bonds.iter().map(|b| b.0).collect();
        let mut states: Vec<BondState> = bonds.iter().map(|b| b.1).collect();
        let mut outs = stale_outputs(bonds.len());
        assert_eq!(
            one_by_one(&model, &kin, &mut states, &mut outs),
            Ok(Some(k)),
            "the reference: bond {k} first"
        );
        check_scattered(p, &bonds).unwrap();
    }
}

/// 17 intact bonds with usable kinematics whose results under `model` are
/// finite, so that every chunk runs in lanes.
fn good_bonds(model: &BondModel, runner: &mut TestRunner) -> Vec<(PairKinematics, BondState)> {
    let good: Vec<(PairKinematics, BondState)> = prop::collection::vec(bond(), 400)
        .new_tree(runner)
        .unwrap()
        .current()
        .into_iter()
        .filter(|(k, s)| {
            let (mut s, mut o) = (*s, BondOutput::default());
            s.status() == BondStatus::Intact
                && model.step(k, DT, &mut s, &mut o).is_ok()
                && o.status == BondStatus::Intact as i32
                && bond_finite(&s, &o)
        })
        .take(17)
        .collect();
    assert_eq!(good.len(), 17);
    good
}

/// Numbers near the largest double that the exact checks accept are
/// accepted in lanes too: slots of switched-off laws whose sum stays
/// finite name no bond, and velocities whose sum overflows (each finite,
/// their difference 0) are stepped, in lanes as one step per bond does.
#[test]
fn large_finite_numbers_pass_the_checks_as_one_by_one() {
    let mut runner = TestRunner::deterministic();
    let base = any_params().new_tree(&mut runner).unwrap().current();
    for features in COMPILED_ALONE {
        let p = switched_on(features, base);
        let model = BondModel::new(p).unwrap();
        let good = good_bonds(&model, &mut runner);
        for k in 0..12 {
            let mut bonds = good.clone();
            if features & (TWIST | BEND) == 0 {
                for b in [k, k + 5] {
                    bonds[b].1.twist_max = 1.7e308;
                    bonds[b].1.bend_opposite = -1.7e308;
                }
                let kin: Vec<PairKinematics> = bonds.iter().map(|b| b.0).collect();
                let mut states: Vec<BondState> = bonds.iter().map(|b| b.1).collect();
                let mut outs = stale_outputs(bonds.len());
                assert_eq!(
                    one_by_one(&model, &kin, &mut states, &mut outs),
                    Ok(None),
                    "the reference: no bond"
                );
            }
            // moving together: the relative velocity the laws read is 0
            let kin = &mut bonds[k + 2].0;
            (kin.v_i, kin.v_j) = ([1.2e308, 1.2e308, 0.0], [1.2e308, 1.2e308, 0.0]);
            check_scattered(p, &bonds).unwrap();
        }
    }
}

/// The lane kernel is what runs here (CI machines have AVX2), and the
/// scalar one can still be chosen: the tests above exercise both.
#[test]
fn scattered_step_runs_in_lanes_where_the_cpu_has_them() {
    let model = BondModel::new(common::params()).unwrap();
    #[cfg(target_arch = "x86_64")]
    {
        if is_x86_feature_detected!("avx2") {
            assert_ne!(model.simd(), Simd::Scalar);
            assert!(model.clone().with_simd(Simd::Avx2).is_some());
        }
    }
    let scalar = model.with_simd(Simd::Scalar).unwrap();
    assert_eq!(scalar.simd(), Simd::Scalar);
}

/// LIGGGHTS-INL's law (`inl_compatible`) has no lane step: the model steps
/// it one bond at a time on every path, with the bits of a single step,
/// and offers no other instruction set.
#[test]
fn inl_compatible_runs_scalar_on_every_path_with_the_bits_of_a_single_step() {
    let (bonds, base) = twenty_bonds_and_params();
    for (damping, damping_smooth, stress_break) in [(0, 0, 0), (1, 0, 1), (1, 1, 0)] {
        let p = BondParams {
            inl_compatible: 1,
            damping,
            damping_smooth,
            stress_break,
            eta_fn: 0.3,
            eta_ft: 0.2,
            ..base
        };
        let model = BondModel::new(p).unwrap();
        assert_eq!(model.simd(), Simd::Scalar);
        #[cfg(target_arch = "x86_64")]
        assert!(model.clone().with_simd(Simd::Avx2).is_none());
        assert_eq!(check_scattered(p, &bonds).unwrap(), 1, "the scalar path alone");
    }
}
