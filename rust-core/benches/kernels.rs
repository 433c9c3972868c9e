//! Cost of one bond step and one contact step, per element.
//!
//! Run with `cargo bench --bench kernels` (or `bench/bond_cost.sh` at the
//! repository root, which also prints a compact table).
//!
//! Every figure is the time of one `BondModel::step_batch` /
//! `VoigtModel::step` sweep over `n` pairs divided by `n` (criterion
//! `Throughput::Elements(n)`), for `n = 1e3` (state, kinematics and output
//! all in cache) and `n = 1e6` (about 0.5 GB streamed per sweep: memory
//! bound).
//!
//! Kinematics: pairs of random radius and random orientation, at a distance
//! within +-0.1 % of the rest length (half of them in tension, half in
//! compression), with random small velocities and spins. Several such frames
//! are prepared per pair (8 for 1e3 pairs, 2 for 1e6), with independent
//! stretches, axes turned slightly and independent velocities; successive
//! sweeps cycle through them, so the bonds keep loading and unloading (every
//! branch of every hysteresis loop is visited, and the branch differs from
//! bond to bond) and their state keeps evolving. With only two alternating
//! frames, 1e3 bonds repeat one short pattern of branch outcomes that the
//! branch predictor learns entirely, which flatters code that branches on
//! the data (no large simulation offers that); `GRANBOND_BENCH_FRAMES=2`
//! shows that case.
//! Breakage is off (distance mode, infinite `max_distance`), so no bond ever
//! breaks.
//!
//! Clock: the CPU time of the benchmark thread (`CLOCK_THREAD_CPUTIME_ID`),
//! so that time spent descheduled on a shared, loaded machine is not
//! counted; on an idle machine it equals wall time. Set
//! `GRANBOND_BENCH_CLOCK=wall` to measure wall time instead.

use criterion::measurement::{Measurement, ValueFormatter};
use criterion::{
    black_box, criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion, SamplingMode,
    Throughput,
};
use granbond::bond::{BondModel, BondOutput, BondParams, BondState, BondStatus, Simd, BOND_STATE_LEN};
use granbond::contact::{ContactOutput, ContactState, VoigtModel, VoigtParams};
use granbond::ffi::bond::{granbond_bond_compute, granbond_bond_model_new};
use granbond::ffi::Status;
use granbond::kinematics::PairKinematics;
use std::time::Duration;

#[path = "fixtures/full_bond.rs"]
mod full_bond;
use full_bond::full_bond;

const IN_CACHE: usize = 1_000;
const MEMORY_BOUND: usize = 1_000_000;
const DT: f64 = 1.0e-6;
/// Mean sphere radius (m).
const RADIUS: f64 = 1.0e-3;

/// Thread CPU time (default) or wall time, in nanoseconds.
struct Clock {
    id: libc::clockid_t,
}

impl Clock {
    fn from_env() -> Self {
        let wall = std::env::var("GRANBOND_BENCH_CLOCK").is_ok_and(|v| v == "wall");
        Self {
            id: if wall {
                libc::CLOCK_MONOTONIC
            } else {
                libc::CLOCK_THREAD_CPUTIME_ID
            },
        }
    }

    fn now(&self) -> u64 {
        let mut t = libc::timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: valid clock id and out-pointer.
        let rc = unsafe { libc::clock_gettime(self.id, &mut t) };
        assert_eq!(rc, 0, "clock_gettime failed");
        t.tv_sec as u64 * 1_000_000_000 + t.tv_nsec as u64
    }
}

struct Nanoseconds;

impl ValueFormatter for Nanoseconds {
    fn scale_values(&self, typical: f64, values: &mut [f64]) -> &'static str {
        let (factor, unit) = if typical < 1e3 {
            (1.0, "ns")
        } else if typical < 1e6 {
            (1e-3, "µs")
        } else if typical < 1e9 {
            (1e-6, "ms")
        } else {
            (1e-9, "s")
        };
        values.iter_mut().for_each(|v| *v *= factor);
        unit
    }

    fn scale_throughputs(&self, _typical: f64, throughput: &Throughput, values: &mut [f64]) -> &'static str {
        let per = match *throughput {
            Throughput::Bytes(n) | Throughput::BytesDecimal(n) | Throughput::Elements(n) => n as f64,
        };
        // Nanoseconds per element: the figure this benchmark is about.
        values.iter_mut().for_each(|v| *v /= per);
        "ns/elem"
    }

    fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
        "ns"
    }
}

impl Measurement for Clock {
    type Intermediate = u64;
    type Value = u64;

    fn start(&self) -> u64 {
        self.now()
    }
    fn end(&self, start: u64) -> u64 {
        self.now().saturating_sub(start)
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }
    fn zero(&self) -> u64 {
        0
    }
    fn to_f64(&self, v: &u64) -> f64 {
        *v as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        &Nanoseconds
    }
}

/// splitmix64: deterministic, dependency-free.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [-a, a).
    fn sym(&mut self, a: f64) -> f64 {
        a * (2.0 * self.unit() - 1.0)
    }

    fn vec(&mut self, a: f64) -> [f64; 3] {
        [self.sym(a), self.sym(a), self.sym(a)]
    }

    /// Uniform on the unit sphere.
    fn direction(&mut self) -> [f64; 3] {
        loop {
            let v = self.vec(1.0);
            let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if l2 > 1e-4 && l2 <= 1.0 {
                let l = l2.sqrt();
                return [v[0] / l, v[1] / l, v[2] / l];
            }
        }
    }
}

fn normalised(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / l, v[1] / l, v[2] / l]
}

/// `frames` frames of kinematics for `n` pairs, and the rest length of each
/// pair. `gap(rng, r0)` gives the centre distance of a frame.
struct Pairs {
    frames: Vec<Vec<PairKinematics>>,
    rest: Vec<f64>,
}

impl Pairs {
    /// The kinematics of sweep number `sweep`.
    fn frame(&self, sweep: usize) -> &[PairKinematics] {
        &self.frames[sweep % self.frames.len()]
    }
}

fn pairs(n: usize, frames: usize, seed: u64, gap: impl Fn(&mut Rng, f64) -> f64) -> Pairs {
    let mut rng = Rng(seed);
    let mut out: Vec<Vec<PairKinematics>> = (0..frames).map(|_| Vec::with_capacity(n)).collect();
    let mut rest = Vec::with_capacity(n);
    for _ in 0..n {
        let radius_i = RADIUS * (0.8 + 0.4 * rng.unit());
        let radius_j = RADIUS * (0.8 + 0.4 * rng.unit());
        let r0 = radius_i + radius_j;
        let x_j = rng.vec(0.05);
        let axis = rng.direction();
        for (f, frame) in out.iter_mut().enumerate() {
            // The axis wanders by about 1e-3 rad from frame to frame.
            let t = if f == 0 { [0.0; 3] } else { rng.vec(1.0e-3) };
            let axis = normalised([axis[0] + t[0], axis[1] + t[1], axis[2] + t[2]]);
            let r = gap(&mut rng, r0);
            frame.push(PairKinematics {
                x_i: [x_j[0] + r * axis[0], x_j[1] + r * axis[1], x_j[2] + r * axis[2]],
                x_j,
                v_i: rng.vec(1.0e-2),
                v_j: rng.vec(1.0e-2),
                w_i: rng.vec(1.0),
                w_j: rng.vec(1.0),
                radius_i,
                radius_j,
            });
        }
        rest.push(r0);
    }
    Pairs { frames: out, rest }
}

/// Frames per pair: enough that the sequence of branch outcomes over a run
/// does not repeat within what a branch predictor can learn (for 1e3 pairs
/// and only two alternating frames it learns the whole pattern, which no
/// real simulation offers), while 1e3 pairs still fit in L2.
fn frame_count(n: usize) -> usize {
    let default = if n >= MEMORY_BOUND { 2 } else { 8 };
    std::env::var("GRANBOND_BENCH_FRAMES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Bonds stretched or compressed by up to 0.1 % of their rest length.
fn bond_pairs(n: usize) -> Pairs {
    pairs(n, frame_count(n), 0x5EED_B0D5 ^ n as u64, |rng, r0| {
        r0 * (1.0 + rng.sym(1.0e-3))
    })
}

/// Contacts with overlaps up to 1 % of the radius sum; about one pair in
/// eleven is apart (a neighbour-list pair that does not touch).
fn contact_pairs(n: usize) -> Pairs {
    pairs(n, frame_count(n), 0xC0_47AC7 ^ n as u64, |rng, r0| {
        r0 * (1.0 - (1.1e-2 * rng.unit() - 1.0e-3))
    })
}

/// Bond variants: name and parameters. `zeroed_*` keep every switch on but
/// zero the stiffnesses of some laws: compare them with the reduced kernel
/// that switches those laws off (`zeroed_twist_bend` vs `normal_shear`,
/// `zeroed_shear_twist_bend` vs `normal_only`).
fn bond_variants() -> Vec<(&'static str, BondParams)> {
    let full = full_bond(RADIUS);
    let no_twist_bend = BondParams {
        twist: 0,
        bend: 0,
        ..full
    };
    let zero_twist_bend = BondParams {
        k_tn: 0.0,
        ku_tn: 0.0,
        kc_tn: 0.0,
        k_tt: 0.0,
        ku_tt: 0.0,
        kc_tt: 0.0,
        ..full
    };
    vec![
        ("full_6dof", full),
        ("no_twist", BondParams { twist: 0, ..full }),
        ("no_bend", BondParams { bend: 0, ..full }),
        ("normal_shear", no_twist_bend),
        (
            "normal_only",
            BondParams {
                shear: 0,
                ..no_twist_bend
            },
        ),
        (
            "tension_only",
            BondParams {
                compression: 0,
                shear: 0,
                ..no_twist_bend
            },
        ),
        ("damping_off", BondParams { damping: 0, ..full }),
        (
            "smooth_damping",
            BondParams {
                damping_smooth: 1,
                ..full
            },
        ),
        ("zeroed_twist_bend", zero_twist_bend),
        (
            "zeroed_shear_twist_bend",
            BondParams {
                k_ft: 0.0,
                ..zero_twist_bend
            },
        ),
    ]
}

fn fresh_states(p: &Pairs) -> Vec<BondState> {
    p.rest.iter().map(|&r0| BondState::created(r0)).collect()
}

fn configure(group: &mut BenchmarkGroup<'_, Clock>, n: usize) {
    group.throughput(Throughput::Elements(n as u64));
    if n >= MEMORY_BOUND {
        // ~50 ms per sweep: a few sweeps per sample, every sample alike.
        group
            .sampling_mode(SamplingMode::Flat)
            .sample_size(10)
            .warm_up_time(Duration::from_millis(600))
            .measurement_time(Duration::from_secs(3));
    } else {
        group
            .sample_size(40)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_millis(1500));
    }
}

fn size_label(n: usize) -> &'static str {
    if n >= MEMORY_BOUND {
        "1e6"
    } else {
        "1e3"
    }
}

/// Checks after a run that the bonds were neither broken nor blown up.
fn assert_sane(name: &str, states: &[BondState], outs: &[BondOutput]) {
    let intact = states.iter().all(|s| s.status() == BondStatus::Intact);
    let finite = outs.iter().all(|o| {
        o.force_i
            .iter()
            .chain(&o.torque_i)
            .chain(&o.torque_j)
            .all(|x| x.is_finite())
    });
    assert!(
        intact && finite,
        "{name}: a bond broke or its loads are not finite"
    );
}

fn bench_bonds(c: &mut Criterion<Clock>, n: usize) {
    let pairs = bond_pairs(n);
    let mut group = c.benchmark_group(format!("bond_{}", size_label(n)));
    configure(&mut group, n);
    for (name, params) in bond_variants() {
        let model = BondModel::new(params).expect("valid bond parameters");
        let mut states = fresh_states(&pairs);
        let mut outs = vec![BondOutput::default(); n];
        let mut sweep = 0usize;
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| {
                let kin = pairs.frame(sweep);
                sweep += 1;
                model
                    .step_batch(black_box(kin), black_box(DT), &mut states, &mut outs)
                    .expect("finite kinematics");
            })
        });
        assert_sane(name, &states, &outs);
        black_box(&outs);
    }
    group.finish();
}

/// `f64` slots per pair of an engine's contact history that holds a bond
/// state (LIGGGHTS keeps the bond's slots among other per-contact data, in
/// pages in the order of its neighbour lists).
const HISTORY_RECORD: usize = 32;

/// `BondModel::step_scattered`, one call per sweep as the LIGGGHTS adapter
/// makes it, over states that lie apart in memory: each at the start of a
/// record of [`HISTORY_RECORD`] `f64`, in the order of the pairs. Variants:
/// the instruction sets of `step_scattered` (`scattered_scalar`,
/// `scattered_avx2`, `scattered_avx512`, those this CPU runs), and `single` =
/// one `BondModel::step` per bond over the same states. `full_6dof` bonds;
/// `n` = 1e3 (in cache) and 1e5 (25 MB of records).
fn bench_scattered(c: &mut Criterion<Clock>, n: usize) {
    let pairs = bond_pairs(n);
    let label = if n >= 100_000 { "1e5" } else { "1e3" };
    let mut group = c.benchmark_group(format!("scattered_{label}"));
    configure(&mut group, n);
    let base = BondModel::new(full_bond(RADIUS)).expect("valid bond parameters");
    let mut variants: Vec<(String, Option<BondModel>)> = vec![("single".into(), None)];
    for simd in [Simd::Scalar, Simd::Avx2, Simd::Avx512] {
        if let Some(m) = base.clone().with_simd(simd) {
            variants.push((format!("scattered_{simd:?}").to_lowercase(), Some(m)));
        }
    }
    for (name, model) in variants {
        let mut records = vec![[0.0f64; HISTORY_RECORD]; n];
        for (record, &r0) in records.iter_mut().zip(&pairs.rest) {
            record[..BOND_STATE_LEN].copy_from_slice(BondState::created(r0).as_slots());
        }
        let mut outs = vec![BondOutput::default(); n];
        let mut sweep = 0usize;
        let mut states: Vec<&mut BondState> = records
            .iter_mut()
            .map(|r| BondState::from_slots_mut((&mut r[..BOND_STATE_LEN]).try_into().unwrap()))
            .collect();
        group.bench_function(BenchmarkId::new(name.as_str(), n), |b| {
            b.iter(|| {
                let kin = pairs.frame(sweep);
                sweep += 1;
                match &model {
                    Some(m) => m
                        .step_scattered(black_box(kin), black_box(DT), &mut states, &mut outs)
                        .map(drop)
                        .expect("finite kinematics"),
                    None => {
                        for ((k, s), o) in black_box(kin).iter().zip(states.iter_mut()).zip(outs.iter_mut()) {
                            base.step(k, DT, s, o).expect("finite kinematics");
                        }
                    }
                }
            })
        });
        let states: Vec<BondState> = states.iter().map(|s| **s).collect();
        assert_sane(&name, &states, &outs);
        black_box(&outs);
    }
    group.finish();
}

/// The sweep of `bond_1e3/full_6dof` one bond per C call (pointer checks,
/// `catch_unwind`, error-slot reset on every call): the cost of the
/// boundary, against `scattered_1e3/single` (the same steps in Rust).
fn bench_ffi(c: &mut Criterion<Clock>) {
    let n = IN_CACHE;
    let pairs = bond_pairs(n);
    let params = full_bond(RADIUS);
    let mut model = std::ptr::null_mut();
    // SAFETY: valid pointers to a parameter struct and an out-pointer.
    let status = unsafe { granbond_bond_model_new(&params, &mut model) };
    assert_eq!(status, Status::Ok);
    let mut states = fresh_states(&pairs);
    let mut outs = vec![BondOutput::default(); n];
    let mut sweep = 0usize;
    let mut group = c.benchmark_group("ffi_1e3");
    configure(&mut group, n);
    group.bench_function(BenchmarkId::new("full_6dof_ffi_single", n), |b| {
        b.iter(|| {
            let kin = pairs.frame(sweep);
            sweep += 1;
            for ((k, s), o) in kin.iter().zip(states.iter_mut()).zip(outs.iter_mut()) {
                // SAFETY: one bond's kinematics, state and output; the model is live.
                let status = unsafe {
                    granbond_bond_compute(
                        black_box(model),
                        k,
                        black_box(DT),
                        s as *mut BondState as *mut f64,
                        o,
                    )
                };
                assert_eq!(status, Status::Ok);
            }
        })
    });
    group.finish();
    assert_sane("full_6dof_ffi_single", &states, &outs);
    // SAFETY: from granbond_bond_model_new, not used again.
    unsafe { granbond::ffi::bond::granbond_bond_model_free(model) };
}

fn bench_contacts(c: &mut Criterion<Clock>, n: usize) {
    let pairs = contact_pairs(n);
    let mut group = c.benchmark_group(format!("contact_{}", size_label(n)));
    configure(&mut group, n);
    for (name, rolling) in [("voigt_rolling", 1), ("voigt_no_rolling", 0)] {
        let model = VoigtModel::new(VoigtParams {
            rolling,
            ..VoigtParams::default()
        })
        .expect("valid contact parameters");
        let mut states = vec![ContactState::default(); n];
        let mut outs = vec![ContactOutput::default(); n];
        let mut sweep = 0usize;
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| {
                let kin = pairs.frame(sweep);
                sweep += 1;
                let dt = black_box(DT);
                for ((k, s), o) in black_box(kin).iter().zip(states.iter_mut()).zip(outs.iter_mut()) {
                    model.step(k, dt, s, o).expect("finite kinematics");
                }
            })
        });
        let finite = outs
            .iter()
            .all(|o| o.force_i.iter().chain(&o.torque_i).all(|x| x.is_finite()));
        assert!(finite, "{name}: contact loads are not finite");
        black_box(&outs);
    }
    group.finish();
}

fn in_cache(c: &mut Criterion<Clock>) {
    bench_bonds(c, IN_CACHE);
    bench_scattered(c, IN_CACHE);
    bench_scattered(c, 100_000);
    bench_ffi(c);
    bench_contacts(c, IN_CACHE);
}

fn memory_bound(c: &mut Criterion<Clock>) {
    bench_bonds(c, MEMORY_BOUND);
    bench_contacts(c, MEMORY_BOUND);
}

criterion_group! {
    name = benches;
    // 100k bootstrap resamples take longer than a measurement here (no rayon).
    config = Criterion::default()
        .with_measurement(Clock::from_env())
        .nresamples(20_000)
        .without_plots();
    targets = in_cache, memory_bound
}
criterion_main!(benches);
