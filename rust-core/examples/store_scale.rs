//! What the bond store costs at scale, alone (no engine): the bytes a bond
//! takes (the store's own count and the process's resident memory, both
//! over the bonds), the time of a link per bond, and the time per
//! bond-step of force passes, on a simple cubic lattice of touching
//! spheres with every touching pair bonded (3 bonds an atom).
//!
//!     cargo run --release -p granbond --example store_scale [n ...]
//!
//! `n` spheres a side (default 22 47 100 145: about 3e4, 3e5, 3e6 and 9e6
//! bonds). The figures are in docs/performance.md ("The bond store").

use granbond::bond::{BondModel, BondOutput, BondParams};
use granbond::bond_store::{BondStore, Ids, LinkAtoms, CHUNK};
use granbond::kinematics::PairKinematics;
use granbond::pair_source::AtomArrays;
use std::time::Instant;

const R: f64 = 1e-3;

/// The process's resident memory, in bytes (Linux).
fn resident() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find(|l| l.starts_with("VmRSS:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|kb| kb.parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb * 1024.0)
}

/// The tests' bond with real hysteresis on every law (granbond-test-support),
/// bonding touching spheres at step 1.
fn model() -> BondModel {
    BondModel::new(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        ..granbond_test_support::params()
    })
    .expect("valid parameters")
}

fn main() {
    let sizes: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() {
        vec![22, 47, 100, 145]
    } else {
        sizes
    };
    let model = model();
    println!(
        "{:>10} {:>10} {:>12} {:>12} {:>12} {:>14}",
        "atoms", "bonds", "store B/bond", "RSS B/bond", "link ns/bond", "pass ns/bond-step"
    );
    for n in sizes {
        let atoms = n * n * n;
        let mut x = Vec::with_capacity(3 * atoms);
        let mut v = Vec::with_capacity(3 * atoms);
        for z in 0..n {
            for y in 0..n {
                for xi in 0..n {
                    let k = (xi + n * (y + n * z)) as f64;
                    x.extend([2.0 * R * xi as f64, 2.0 * R * y as f64, 2.0 * R * z as f64]);
                    v.extend([1e-3 * (k * 0.37).sin(), 1e-3 * (k * 0.11).cos(), 0.0]);
                }
            }
        }
        let omega = vec![0.5; 3 * atoms];
        let radius = vec![R; atoms];
        let ids: Vec<i32> = (1..=atoms as i32).collect();
        let types = vec![1i32; atoms];
        let kinds = [-1, -1, -1, 0];
        let before = resident();
        let mut store = BondStore::new();
        store.grow(atoms);
        let link_atoms = LinkAtoms {
            ids: Ids::Narrow(&ids),
            nlocal: atoms,
            x: &x,
            types: &types,
            kinds: &kinds,
            ntypes: 1,
            reach: 0.0,
        };
        store.link(&link_atoms).expect("a well-formed rank");
        // every touching pair, as a pair loop at the creation step finds them
        store.begin_pass(1e-7, true, false);
        let at = |i: usize| [x[3 * i], x[3 * i + 1], x[3 * i + 2]];
        for i in 0..atoms {
            let (xi, yi, zi) = (i % n, (i / n) % n, i / (n * n));
            for (d, next) in [(xi + 1 < n, 1), (yi + 1 < n, n), (zi + 1 < n, n * n)] {
                if !d {
                    continue;
                }
                let j = i + next;
                let k = PairKinematics {
                    x_i: at(i),
                    x_j: at(j),
                    radius_i: R,
                    radius_j: R,
                    ..PairKinematics::default()
                };
                store
                    .try_create(&model, 0, i, j, [i as i64 + 1, j as i64 + 1], &k, 1)
                    .expect("usable kinematics");
            }
        }
        store.finish_pass();
        let t = Instant::now();
        store.link(&link_atoms).expect("a well-formed rank");
        let link_ns = t.elapsed().as_secs_f64() * 1e9;
        let bonds = store.len() as f64;
        let rss = resident() - before;
        let arrays = AtomArrays {
            x: &x,
            v: &v,
            omega: &omega,
            radius: &radius,
        };
        let models = [Some(&model)];
        let (mut ends, mut outs) = ([[0i32; 2]; CHUNK], [BondOutput::default(); CHUNK]);
        let mut force = vec![0.0f64; 3 * atoms];
        let passes = (2e7 / bonds).ceil().max(2.0) as usize;
        let t = Instant::now();
        for _ in 0..passes {
            store.begin_pass(1e-8, true, false);
            loop {
                let got = store
                    .step_next(&models, arrays, Ids::Narrow(&ids), &mut ends, &mut outs)
                    .expect("a usable pass");
                if got == 0 {
                    break;
                }
                // the loads go to the atoms, as an adapter adds them
                for (e, o) in ends[..got].iter().zip(&outs[..got]) {
                    for c in 0..3 {
                        force[3 * e[0] as usize + c] += o.force_i[c];
                        force[3 * e[1] as usize + c] -= o.force_i[c];
                    }
                }
            }
            store.finish_pass();
        }
        let pass_ns = t.elapsed().as_secs_f64() * 1e9 / (passes as f64 * bonds);
        std::hint::black_box(&force);
        println!(
            "{:>10} {:>10} {:>12.1} {:>12.1} {:>12.1} {:>14.1}",
            atoms,
            bonds,
            store.bytes() as f64 / bonds,
            rss / bonds,
            link_ns / bonds,
            pass_ns
        );
    }
}
