//! Instructions per bond-step of `BondModel::step_scattered` on each
//! instruction set, and of one `BondModel::step` per bond: a load-independent
//! measure for a shared machine (valgrind counts instructions; it runs AVX2
//! but not AVX-512).
//!
//!     cargo build --release --example scattered_cost
//!     for sweeps in 1 11; do for path in single scalar avx2; do
//!       valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.$path.$sweeps \
//!         target/release/examples/scattered_cost $path $sweeps; done; done
//!
//! Instructions per bond-step = (Ir at 11 sweeps - Ir at 1) / (10 * BONDS)
//! (the difference removes start-up and set-up). Without valgrind it prints
//! the wall time per bond-step of the sweeps.
//!
//! A third argument names the switches, as in `benches/kernels.rs`:
//! `full_6dof` (the default), `no_twist`, `no_bend`, `normal_shear`,
//! `normal_only`, `tension_only`; a fourth, `switched`, runs the steps that
//! read the switches at run time instead of the ones compiled for them.
//!
//! Bonds: the `full_6dof` parameters of `benches/kernels.rs` with those
//! switches, pairs near their rest length (half stretched, half compressed)
//! with random motion, states in records of 32 `f64` in shuffled order.

use granbond::bond::{BondModel, BondOutput, BondParams, BondState, Simd, BOND_STATE_LEN};
use granbond::kinematics::PairKinematics;
use std::time::Instant;

#[path = "../benches/fixtures/full_bond.rs"]
mod full_bond;
use full_bond::full_bond;

const BONDS: usize = 10_000;
const RECORD: usize = 32;
const FRAMES: usize = 4;
const RADIUS: f64 = 1e-3;

/// A deterministic number in [-1, 1) from `i` (a hash, no dependency).
fn noise(i: u64) -> f64 {
    let mut z = i.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Pair `b` in frame `s`: the stretch and the motion change from frame to
/// frame, so the bonds load and unload.
fn pair(b: usize, s: usize) -> (PairKinematics, f64) {
    let h = |k: u64| noise((b as u64) << 20 | (s as u64) << 8 | k);
    let (ri, rj) = (
        RADIUS * (1.0 + 0.2 * noise(b as u64 * 2)),
        RADIUS * (1.0 + 0.2 * noise(b as u64 * 2 + 1)),
    );
    let axis = [
        noise(b as u64 * 7),
        noise(b as u64 * 7 + 1),
        0.5 + noise(b as u64 * 7 + 2).abs(),
    ];
    let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let r = (ri + rj) * (1.0 + 1e-3 * h(0));
    let v = |k: u64, a: f64| [a * h(k), a * h(k + 1), a * h(k + 2)];
    let kin = PairKinematics {
        x_i: axis.map(|c| c / len * r),
        x_j: [0.0; 3],
        v_i: v(1, 1e-2),
        v_j: v(4, 1e-2),
        w_i: v(7, 1.0),
        w_j: v(10, 1.0),
        radius_i: ri,
        radius_j: rj,
    };
    (kin, ri + rj)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).map(String::as_str).unwrap_or("avx2");
    let sweeps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(11);
    let variant = args.get(3).map(String::as_str).unwrap_or("full_6dof");
    let full = full_bond(RADIUS);
    let params = match variant {
        "full_6dof" => full,
        "no_twist" => BondParams { twist: 0, ..full },
        "no_bend" => BondParams { bend: 0, ..full },
        "normal_shear" => BondParams {
            twist: 0,
            bend: 0,
            ..full
        },
        "normal_only" => BondParams {
            shear: 0,
            twist: 0,
            bend: 0,
            ..full
        },
        "tension_only" => BondParams {
            compression: 0,
            shear: 0,
            twist: 0,
            bend: 0,
            ..full
        },
        other => panic!("unknown switches {other}"),
    };
    let mut base = BondModel::new(params).expect("valid parameters");
    if args.get(4).map(String::as_str) == Some("switched") {
        base = base.switched();
    }
    let model = match path {
        "single" => None,
        "scalar" => Some(base.clone().with_simd(Simd::Scalar).unwrap()),
        "avx2" => Some(base.clone().with_simd(Simd::Avx2).expect("AVX2")),
        "avx512" => Some(base.clone().with_simd(Simd::Avx512).expect("AVX-512")),
        other => panic!("unknown path {other}: single, scalar, avx2 or avx512"),
    };
    // A fixed number of frames, whatever the number of sweeps: the set-up
    // costs the same in every run.
    let frames: Vec<Vec<PairKinematics>> = (0..FRAMES)
        .map(|s| (0..BONDS).map(|b| pair(b, s).0).collect())
        .collect();
    let order: Vec<usize> = {
        let mut o: Vec<usize> = (0..BONDS).collect();
        for i in (1..BONDS).rev() {
            o.swap(
                i,
                ((noise(i as u64 ^ 0xABCD) + 1.0) * 0.5 * (i + 1) as f64) as usize % (i + 1),
            );
        }
        o
    };
    let mut records = vec![[0.0f64; RECORD]; BONDS];
    for b in 0..BONDS {
        records[order[b]][..BOND_STATE_LEN].copy_from_slice(BondState::created(pair(b, 0).1).as_slots());
    }
    let mut slots: Vec<Option<&mut BondState>> = records
        .iter_mut()
        .map(|r| {
            Some(BondState::from_slots_mut(
                (&mut r[..BOND_STATE_LEN]).try_into().unwrap(),
            ))
        })
        .collect();
    let mut states: Vec<&mut BondState> = order.iter().map(|&o| slots[o].take().unwrap()).collect();
    let mut outs = vec![BondOutput::default(); BONDS];
    let start = Instant::now();
    for kin in frames.iter().cycle().take(sweeps) {
        match &model {
            Some(m) => m
                .step_scattered(kin, 1e-6, &mut states, &mut outs)
                .map(drop)
                .unwrap(),
            None => {
                for ((k, s), o) in kin.iter().zip(states.iter_mut()).zip(outs.iter_mut()) {
                    base.step(k, 1e-6, s, o).unwrap();
                }
            }
        }
    }
    let ns = start.elapsed().as_nanos() as f64 / (sweeps * BONDS) as f64;
    let checksum: f64 = outs.iter().map(|o| o.force_i[0] + o.torque_j[2]).sum();
    println!("{path} {variant}: {sweeps} sweeps of {BONDS} bonds, {ns:.1} ns per bond-step (checksum {checksum:e})");
}
