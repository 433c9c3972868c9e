//! The bonds' energy budget (`granbond::bond_store`, docs/models/bond-nonlinear.md,
//! "Energy"): a step's damping and hysteresis never create energy, and a
//! free cluster integrated as the engines integrate it (velocity Verlet)
//! keeps kinetic + stored + dissipated + released energy to the
//! integrator's error, with damping, hysteresis and bonds that break.

use granbond_test_support as common;

use common::strategies::{bond_params, bonded_pair};
use granbond::bond::{BondModel, BondOutput, BondParams, BondStatus};
use granbond::bond_store::{
    creates_here, packed_len_in, step_budget, BondStore, EnergySums, Ids, LinkAtoms, BUDGET_BYTES_PER_BOND,
    CHUNK, DAMPING_LOADS_LEN, DISSIPATED_BYTES_PER_BOND,
};
use granbond::pair_source::AtomArrays;
use proptest::prelude::*;

const R: f64 = common::RADIUS;

proptest! {
    /// The law's own damping work in a step, `-dt dL . V`, and the drop of
    /// the stored energy where the step moved the history are never below
    /// zero (round-off aside), for any bond, motion and history.
    #[test]
    fn a_step_of_damping_or_hysteresis_never_creates_energy(
        p in bond_params(),
        (kin, state) in bonded_pair(),
        dt in 1e-9f64..1e-6,
    ) {
        let model = common::model(p);
        let mut after = state;
        let mut out = BondOutput::default();
        model.step(&kin, dt, &mut after, &mut out).expect("usable kinematics");
        prop_assume!(out.status == BondStatus::Intact as i32);
        let mut previous = [0.0; DAMPING_LOADS_LEN];
        let step = step_budget(&model, &kin, dt, &state, &after, &out, &mut previous);
        let stored = model
            .stored_energy(&state, [1.0, 0.0, 0.0], 0.0, kin.radius_i, kin.radius_j)
            .total()
            .abs();
        // round-off of the energies compared, and of the loads' work
        let work: f64 = out.force_i.iter().chain(&out.torque_i).chain(&out.torque_j).map(|l| l.abs()).sum::<f64>()
            * dt
            * 1e3;
        let tol = 1e-12 * (stored + work) + 1e-30;
        prop_assert!(step.damping_law >= -tol, "damping {:?}, tol {tol}", step);
        prop_assert!(step.hysteresis >= -tol, "hysteresis {:?}, tol {tol}", step);
    }
}

/// Spheres in free flight, integrated as LAMMPS `fix nve/sphere` does.
struct Cluster {
    ids: Vec<i64>,
    x: Vec<f64>,
    v: Vec<f64>,
    omega: Vec<f64>,
    radius: Vec<f64>,
    types: Vec<i32>,
    force: Vec<f64>,
    torque: Vec<f64>,
}

fn mass() -> f64 {
    common::DENSITY * 4.0 / 3.0 * std::f64::consts::PI * R * R * R
}

fn inertia() -> f64 {
    0.4 * mass() * R * R
}

/// A pseudo-random number in [-0.5, 0.5) from `seed` and `k`.
fn wobble(seed: u64, k: u64) -> f64 {
    ((seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(k.wrapping_mul(1442695040888963407))
        >> 33) as f64
        / (1u64 << 31) as f64)
        - 0.5
}

impl Cluster {
    /// `n` x `n` x `n` spheres `spacing` apart, spinning about z at `spin`,
    /// each with a random velocity up to `speed` and spin up to `spin`.
    fn block(n: usize, spacing: f64, speed: f64, spin: f64) -> Self {
        let mut c = Cluster {
            ids: vec![],
            x: vec![],
            v: vec![],
            omega: vec![],
            radius: vec![],
            types: vec![],
            force: vec![],
            torque: vec![],
        };
        let mid = spacing * (n as f64 - 1.0) / 2.0;
        for z in 0..n {
            for y in 0..n {
                for x in 0..n {
                    let id = 1 + (x + n * (y + n * z)) as i64;
                    let p = [x, y, z].map(|q| spacing * q as f64 - mid);
                    let s = id as u64;
                    c.ids.push(id);
                    c.x.extend(p);
                    // a rigid spin about z plus a random part
                    c.v.extend([
                        -spin * p[1] + speed * wobble(s, 1),
                        spin * p[0] + speed * wobble(s, 2),
                        speed * wobble(s, 3),
                    ]);
                    c.omega.extend([
                        spin * wobble(s, 4),
                        spin * wobble(s, 5),
                        spin * (1.0 + wobble(s, 6)),
                    ]);
                    c.radius.push(R);
                    c.types.push(1);
                }
            }
        }
        c.force = vec![0.0; c.x.len()];
        c.torque = vec![0.0; c.x.len()];
        c
    }

    fn arrays(&self) -> AtomArrays<'_> {
        AtomArrays {
            x: &self.x,
            v: &self.v,
            omega: &self.omega,
            radius: &self.radius,
        }
    }

    fn kinetic(&self) -> f64 {
        let sq = |a: &[f64]| a.iter().map(|c| c * c).sum::<f64>();
        0.5 * mass() * sq(&self.v) + 0.5 * inertia() * sq(&self.omega)
    }

    /// Half a kick of the latest loads.
    fn kick(&mut self, dt: f64) {
        let (m, i) = (mass(), inertia());
        for c in 0..self.v.len() {
            self.v[c] += 0.5 * dt * self.force[c] / m;
            self.omega[c] += 0.5 * dt * self.torque[c] / i;
        }
    }

    /// A pass over the store (`dt` 0: a setup pass): the bonds' loads
    /// into the spheres' forces and torques.
    fn pass(&mut self, store: &mut BondStore, model: &BondModel, dt: f64, create: bool) {
        self.force.fill(0.0);
        self.torque.fill(0.0);
        store.begin_pass(dt, dt > 0.0, false);
        if create {
            let kinds = [-1, -1, -1, 0];
            let atoms = LinkAtoms {
                ids: Ids::Wide(&self.ids),
                nlocal: self.ids.len(),
                x: &self.x,
                types: &self.types,
                kinds: &kinds,
                ntypes: 1,
                reach: 0.0,
            };
            store.link(&atoms).expect("a well-formed rank");
            for i in 0..self.ids.len() {
                for j in i + 1..self.ids.len() {
                    let three = |a: &[f64], k: usize| [a[3 * k], a[3 * k + 1], a[3 * k + 2]];
                    let mut k = granbond::kinematics::PairKinematics {
                        x_i: three(&self.x, i),
                        x_j: three(&self.x, j),
                        v_i: three(&self.v, i),
                        v_j: three(&self.v, j),
                        w_i: three(&self.omega, i),
                        w_j: three(&self.omega, j),
                        radius_i: R,
                        radius_j: R,
                    };
                    let owner_j = creates_here(true, true, self.ids[i], self.ids[j], false).expect("local");
                    let (o, p) = if owner_j { (j, i) } else { (i, j) };
                    if owner_j {
                        std::mem::swap(&mut k.x_i, &mut k.x_j);
                        std::mem::swap(&mut k.v_i, &mut k.v_j);
                        std::mem::swap(&mut k.w_i, &mut k.w_j);
                    }
                    store
                        .try_create(model, 0, o, p, [self.ids[o], self.ids[p]], &k, 1)
                        .expect("usable kinematics");
                }
            }
        }
        let (mut ends, mut outs) = ([[0; 2]; CHUNK], [BondOutput::default(); CHUNK]);
        loop {
            let n = store
                .step_next(
                    &[Some(model)],
                    self.arrays(),
                    Ids::Wide(&self.ids),
                    &mut ends,
                    &mut outs,
                )
                .expect("a usable pass");
            if n == 0 {
                break;
            }
            for (e, o) in ends[..n].iter().zip(&outs[..n]) {
                let (i, j) = (e[0] as usize, e[1] as usize);
                for c in 0..3 {
                    self.force[3 * i + c] += o.force_i[c];
                    self.force[3 * j + c] -= o.force_i[c];
                    self.torque[3 * i + c] += o.torque_i[c];
                    self.torque[3 * j + c] += o.torque_j[c];
                }
            }
        }
        store.finish_pass();
    }
}

/// What a run of the cluster shows.
struct Run {
    /// (kinetic + stored + dissipated + released) - its start, largest
    /// size, as a fraction of the start.
    drift: f64,
    start: f64,
    sums: EnergySums,
    broken: i64,
    created: i64,
    bytes: usize,
}

/// The cluster's bonds of `p` over `steps` steps of `dt`, the budget kept.
fn run(p: BondParams, dt: f64, steps: usize) -> Run {
    let model = common::model(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        ..p
    });
    let mut c = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    let mut store = BondStore::new();
    store.grow(c.ids.len());
    store.keep_energy_budget(true, false);
    // step 1 creates the bonds; its start is the budget's start
    let mut start = None;
    let mut drift: f64 = 0.0;
    c.pass(&mut store, &model, 0.0, false);
    for step in 1..=steps {
        c.kick(dt);
        for k in 0..c.x.len() {
            c.x[k] += dt * c.v[k];
        }
        c.pass(&mut store, &model, dt, step == 1);
        c.kick(dt);
        let stored = store.stored_energy(&[Some(&model)], c.arrays()).expect("linked");
        let s = store.energy_sums();
        let total = c.kinetic() + stored + s.damping + s.hysteresis + s.released;
        let e0 = *start.get_or_insert(total);
        drift = drift.max((total - e0).abs() / e0);
    }
    let counts = store.counts();
    Run {
        drift,
        start: start.unwrap_or(0.0),
        sums: store.energy_sums(),
        broken: counts.broken(),
        created: counts.created,
        bytes: store.bytes(),
    }
}

/// `p` with every stiffness scaled by `s`.
fn softer(p: BondParams, s: f64) -> BondParams {
    BondParams {
        k_fn1: p.k_fn1 * s,
        ku_fn1: p.ku_fn1 * s,
        kc_fn1: p.kc_fn1 * s,
        k_fn2: p.k_fn2 * s,
        ku_fn2: p.ku_fn2 * s,
        kc_fn2: p.kc_fn2 * s,
        k_ft: p.k_ft * s,
        k_tn: p.k_tn * s,
        ku_tn: p.ku_tn * s,
        kc_tn: p.kc_tn * s,
        k_tt: p.k_tt * s,
        ku_tt: p.ku_tt * s,
        kc_tt: p.kc_tt * s,
        ..p
    }
}

/// The test set's hysteretic bond, softer, damped, breaking by distance.
fn hysteretic_damped_breaking() -> BondParams {
    BondParams {
        damping: 1,
        eta_fn: 0.1,
        eta_ft: 0.1,
        eta_tn: 0.1,
        eta_tt: 0.1,
        max_distance: 2.05 * R + 1e-6,
        ..softer(common::params(), SOFTER)
    }
}

const SOFTER: f64 = 1e-3;

#[test]
fn a_free_cluster_keeps_kinetic_stored_dissipated_and_released_energy() {
    let r = run(hysteretic_damped_breaking(), 1e-8, 10000);
    println!(
        "drift {:.3e} of {:.4e} J; damping {:.3e}, hysteresis {:.3e}, released {:.3e}; {} of {} bonds broke; {} bytes",
        r.drift, r.start, r.sums.damping, r.sums.hysteresis, r.sums.released, r.broken, r.created, r.bytes
    );
    let elastic = run(softer(common::elastic_params(), SOFTER), 1e-8, 10000);
    println!("elastic, undamped, unbreakable: drift {:.3e}", elastic.drift);
    assert!(
        r.broken > 0 && r.broken < r.created,
        "{} of {} bonds broke",
        r.broken,
        r.created
    );
    for (term, value) in [
        ("damping", r.sums.damping),
        ("hysteresis", r.sums.hysteresis),
        ("released", r.sums.released),
    ] {
        assert!(value > 1e-3 * r.start, "{term} took {value:e} J of {:e}", r.start);
    }
    // the integrator's error: that of the same cluster with elastic,
    // undamped bonds that do not break, where kinetic + stored is all
    assert!(
        r.drift < 2.0 * elastic.drift,
        "the budget moved by {:.3e} of itself, the elastic cluster's energy by {:.3e}",
        r.drift,
        elastic.drift
    );
}

#[test]
fn the_budget_costs_nothing_per_bond_until_kept() {
    let model = common::model(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        ..hysteretic_damped_breaking()
    });
    let mut c = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    let mut store = BondStore::new();
    store.grow(c.ids.len());
    c.pass(&mut store, &model, 1e-8, true);
    let without = store.bytes();
    store.keep_energy_budget(true, false);
    let kept = store.bytes();
    store.keep_energy_budget(true, true);
    let per_bond = store.bytes();
    store.keep_energy_budget(false, false);
    assert_eq!(store.bytes(), without, "the budget left bytes behind");
    let n = store.len();
    assert_eq!(kept - without, n * BUDGET_BYTES_PER_BOND);
    assert_eq!(per_bond - kept, n * DISSIPATED_BYTES_PER_BOND);
}

#[test]
fn a_migrating_bond_takes_its_share_of_the_budget_along() {
    let model = common::model(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        ..hysteretic_damped_breaking()
    });
    let mut c = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    let mut store = BondStore::new();
    store.grow(c.ids.len());
    store.keep_energy_budget(true, true);
    c.pass(&mut store, &model, 0.0, false);
    c.pass(&mut store, &model, 1e-8, true);
    for _ in 0..50 {
        for k in 0..c.x.len() {
            c.x[k] += 1e-8 * c.v[k];
        }
        c.pass(&mut store, &model, 1e-8, false);
    }
    // the centre atom owns bonds; its own dissipated energies travel with it
    let centre = 13;
    let owned: Vec<[f64; 2]> = (0..store.len())
        .filter(|&k| store.bond(k).expect("linked").1[0] == centre as i32)
        .map(|k| store.dissipated(k).expect("kept"))
        .collect();
    assert!(!owned.is_empty() && owned.iter().any(|d| d[0] > 0.0), "{owned:?}");
    let mut buf = vec![0.0; store.packed_len(centre)];
    let written = store.pack(centre, true, &mut buf).expect("room");
    assert_eq!(packed_len_in(&buf[..3]), Ok(written), "the head says the length");
    // a store that keeps the budget (migration), and one that does not yet
    // (a restart file read before the run's start says whether it is kept)
    for kept in [true, false] {
        let mut other = BondStore::new();
        other.keep_energy_budget(kept, kept);
        assert_eq!(other.unpack(0, &buf[..written]), Ok(written));
        let mut arrived: Vec<Option<[f64; 2]>> = (0..other.len()).map(|k| other.dissipated(k)).collect();
        // in any order: the owner's list is its own
        let mut want: Vec<Option<[f64; 2]>> = owned.iter().copied().map(Some).collect();
        let by = |d: &Option<[f64; 2]>| d.map(|d| d[0].to_bits());
        want.sort_by_key(by);
        arrived.sort_by_key(by);
        assert_eq!(arrived, want, "kept before: {kept}");
        // a run that does not ask for the budget drops it
        other.keep_energy_budget(false, false);
        assert!((0..other.len()).all(|k| other.dissipated(k).is_none()));
        assert_eq!(other.energy_budget_kept(), (false, false));
    }
}

/// The atoms' shares of their bonds' damping loads (LIGGGHTS-INL's
/// `computeDissipatedEnergy` columns): each atom's is minus the damping
/// force and torque it feels, the loads of the damped pass less those of
/// the same pass undamped, atom by atom; INL's bond/nonlinear files none.
#[test]
fn each_atom_takes_minus_the_damping_loads_it_feels() {
    let damped = BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        max_distance: 4.0 * R,
        ..hysteretic_damped_breaking()
    };
    let undamped = BondParams { damping: 0, ..damped };
    let (md, mu) = (common::model(damped), common::model(undamped));
    let mut c = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    let mut u = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    let (mut sd, mut su) = (BondStore::new(), BondStore::new());
    sd.grow(c.ids.len());
    su.grow(u.ids.len());
    sd.keep_energy_budget(true, false);
    c.pass(&mut sd, &md, 1e-8, true);
    u.pass(&mut su, &mu, 1e-8, true);
    // the same motion for both: the damping changes the loads, not the state
    for _ in 0..20 {
        for k in 0..c.x.len() {
            c.x[k] += 1e-8 * c.v[k];
            u.x[k] = c.x[k];
        }
        c.pass(&mut sd, &md, 1e-8, false);
        u.pass(&mut su, &mu, 1e-8, false);
    }
    let n = c.ids.len();
    let mut table = vec![0.0; 7 * n];
    sd.add_dissipated_shares(&[Some(&md)], &mut table, 7, 1, n)
        .expect("kept and linked");
    let (mut worst, mut largest) = (0.0f64, 0.0f64);
    for a in 0..n {
        assert_eq!(table[7 * a], 0.0, "column 0 is not a share");
        for q in 0..3 {
            let force = c.force[3 * a + q] - u.force[3 * a + q];
            let torque = c.torque[3 * a + q] - u.torque[3 * a + q];
            worst = worst
                .max((table[7 * a + 1 + q] + force).abs())
                .max((table[7 * a + 4 + q] + torque).abs());
            largest = largest.max(force.abs() * R).max(torque.abs());
        }
    }
    assert!(largest > 0.0, "the damping acted");
    assert!(
        worst <= 1e-12 * largest / R,
        "off by {worst:.3e}, damping loads up to {largest:.3e}"
    );
    // LIGGGHTS-INL's bond/nonlinear files none
    let inl = common::model(BondParams {
        inl_compatible: 1,
        ..damped
    });
    let mut si = BondStore::new();
    si.grow(n);
    si.keep_energy_budget(true, false);
    let mut ci = Cluster::block(3, 2.05 * R, 0.2, 40.0);
    ci.pass(&mut si, &inl, 1e-8, true);
    ci.pass(&mut si, &inl, 1e-8, false);
    let mut none = vec![0.0; 7 * n];
    si.add_dissipated_shares(&[Some(&inl)], &mut none, 7, 1, n)
        .expect("kept and linked");
    assert!(none.iter().all(|&s| s == 0.0));
}
