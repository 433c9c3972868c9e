//! Several bonds per instruction: the assembled step ([`super::step`]) on
//! packed registers of 4 or 8 bonds ([`Pack`]).
//!
//! A chunk of bonds is transposed from the engine's structs into lanes (one
//! register per quantity), advanced, and transposed back. Every lane
//! gets the bits one [`super::scalar::bond_step`] gives its bond: the laws
//! are the same code, each lane operation is the `f64` operation (see
//! [`crate::real`]), and nothing mixes lanes, so it does not matter which
//! lane or chunk a bond lands in.
//!
//! Each number is checked ([`super::finite`]) as it passes: added to its
//! sum when it is loaded or written, so that the checks hold no number of
//! their own.
//!
//! What `bond_step` decides per bond with a jump is a mask here, except
//! what is rare and has side effects of its own: a chunk with a bond that
//! is not intact, whose kinematics are unusable or that breaks by distance
//! is left to the scalar kernel, which zeroes the first kind and reports
//! the second with its index.

use super::atom_loads::{LoadSink, Rows};
use super::features::{BEND, SHEAR, TWIST};
use super::finite::{bond_finite, results_finite_summed, results_surely_finite, BatchResult};
use super::laws::BondLaws;
use super::scalar::one_by_one;
use super::state::{slot_of, BondOutput, BondState, BondStatus, BOND_STATE_LEN};
use super::step::{advance, breaks_by_distance, relative, HistoryIo, MotionSource};
use super::switches::Switches;
use super::twist_bend::{BendHistory, TwistHistory};
use crate::kinematics::{axis, separated, PairKinematics};
use crate::pair_source::PairSource;
use crate::real::packed::Lane3;
use crate::real::packed::Pack;
use crate::vector::{Vector, V3};
use std::borrow::{Borrow, BorrowMut};

/// [`one_by_one`] in chunks of `P::WIDTH` lanes; the bonds after the last full
/// chunk one by one. Each chunk's loads go to `sink` as soon as it is
/// stepped: from the lanes where it can take them so, else from the
/// outputs.
#[inline(always)]
pub(crate) fn in_chunks<S: Switches, P: Pack, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
    laws: &BondLaws,
    kin: &K,
    dt: f64,
    states: &mut [T],
    outs: &mut [BondOutput],
    sink: &LoadSink<'_>,
) -> BatchResult {
    let count = kin.len().min(states.len()).min(outs.len());
    let mut first = None;
    let mut start = 0;
    while start + P::WIDTH <= count {
        let end = start + P::WIDTH;
        let chunk = &mut states[start..end];
        let outs_of = &mut outs[start..end];
        let outcome = match P::WIDTH {
            4 => step_chunk::<S, P, K, 4>(laws, kin, start, dt, &mut lanes(chunk), outs_of, sink),
            8 => step_chunk::<S, P, K, 8>(laws, kin, start, dt, &mut lanes(chunk), outs_of, sink),
            _ => unreachable!("lanes of 4 or 8"),
        };
        let (found, added) = match outcome {
            // rare: which lane, from what was stored
            Some((finite, _)) if !P::all(finite) => (
                (start..end).find(|&b| !bond_finite(states[b].borrow(), &outs[b])),
                false,
            ),
            Some((_, added)) => (None, added),
            None => (
                one_by_one::<S, K, T>(laws, kin, start..end, dt, states, outs)?,
                false,
            ),
        };
        if !added {
            sink.add_outputs(start..end, outs);
        }
        first = first.or(found);
        start = end;
    }
    let found = one_by_one::<S, K, T>(laws, kin, start..count, dt, states, outs)?;
    sink.add_outputs(start..count, outs);
    Ok(first.or(found))
}

/// The chunk's states, one reference a lane, in an array of the step's
/// own: the step's stores to the states cannot change it, so the
/// references are read once (from the caller's slice, every store would
/// make the compiler read them again).
#[inline(always)]
fn lanes<const N: usize, T: BorrowMut<BondState>>(chunk: &mut [T]) -> [&mut BondState; N] {
    let mut chunk = chunk.iter_mut();
    std::array::from_fn(|_| chunk.next().expect("a state a lane").borrow_mut())
}

/// Advances the `P::WIDTH` bonds of a chunk, from bond `first` of `kin` on,
/// in lanes, and returns a mask whose lanes are all true only if every
/// bond's results are finite and none broke (a false lane leaves the caller
/// to find which bond, if any, is not finite), and whether their loads went
/// to `sink` from the lanes (only where every lane is true; else the caller
/// adds them from the outputs); or returns `None` without touching anything
/// when one of them is not intact or its kinematics are not surely usable
/// (the scalar kernel then decides).
#[inline(always)]
fn step_chunk<S: Switches, P: Pack, K: PairSource + ?Sized, const N: usize>(
    laws: &BondLaws,
    kin: &K,
    first: usize,
    dt: f64,
    states: &mut [&mut BondState; N],
    outs: &mut [BondOutput],
    sink: &LoadSink<'_>,
) -> Option<(P::Mask, bool)> {
    let (states, outs) = (&mut states[..], &mut outs[..N]);
    let kin = |lane: usize| kin.pair(first + lane);
    // A positive rest length: intact (`BondState::rest`).
    let r0: P = gather(states, |s: &BondState| s.rest);
    if !P::all(r0.gt(P::splat(0.0))) {
        return None;
    }
    let on = |bits| S::of(laws).any(bits);
    let (x_i, x_j) = (lanes3(kin, |k| k.x_i), lanes3(kin, |k| k.x_j));
    let d = x_i - x_j;
    let r2 = d.norm_squared();
    let line = axis(d, r2);
    let mut motion = LaneMotion {
        kin,
        sum: ((x_i.x + x_i.y) + (x_i.z + x_j.x)) + (x_j.y + x_j.z),
        positive: P::mask(true),
        velocities: false,
        spins: false,
    };
    let relative = relative::<S, P, V3<P>>(laws, &mut motion, line, r0);
    let finite = motion.finite();
    let positive = motion.positive;
    // Decided before the step writes anything, and after the numbers read
    // are reduced to what the laws need, so that they are not held to the
    // branch. A bond broken by distance is rare, and its lane would need
    // its history kept aside: the scalar kernel steps such a chunk too.
    let usable = finite & positive & separated(r2);
    if !P::all(usable) || P::any(breaks_by_distance(laws, line.r)) {
        return None;
    }

    // The slots after the last one a law switched on uses stay in memory:
    // the step leaves them alone, and only the results check reads them.
    // (Where the bits are read at run time, a rest of varying length costs
    // more than it saves: every slot is moved.)
    let live = if S::FIXED {
        live_slots(on(SHEAR), on(TWIST), on(BEND))
    } else {
        BOND_STATE_LEN
    };
    let mut history = Lanes {
        states,
        outs,
        live,
        sum: r0,
        loads_sum: P::splat(0.0),
    };
    let loads = advance::<S, P, V3<P>, _>(laws, &relative, P::splat(dt), &mut history);
    let (states, outs, state_sum, mut loads_sum) =
        (history.states, history.outs, history.sum, history.loads_sum);

    // A bond that broke exerts nothing, and its status says so. Rare: a
    // branch rather than a blend per number.
    let broken = loads.mode.gt(P::splat(0.0));
    if P::any(broken) {
        loads.mode.for_each_lane(|i, mode| {
            if mode != 0.0 {
                states[i].mark_broken();
            }
        });
    }

    // The sums took the bonds to hold (the status intact, the loads as
    // computed): a lane that broke is left to the caller, who checks it
    // exactly from what was stored.
    let (ti, tj) = (loads.torque_i, loads.torque_j);
    for x in [ti.x, ti.y, ti.z, tj.x, tj.y, tj.z] {
        loads_sum = loads_sum + x;
    }
    let scalars = [loads.normal_force, loads.sigma, loads.tau, loads.delta];
    let finite = if live == BOND_STATE_LEN {
        results_finite_summed(loads_sum, scalars, state_sum)
    } else {
        results_surely_finite(loads_sum, scalars, state_sum, |lane| {
            &states[lane].as_slots()[live..]
        })
    };
    let held = finite & !broken;

    // Back into the structs one quantity at a time: each register is
    // stored once and its lanes copied out. The loads go to the atoms
    // from the registers where every lane holds (else the caller adds
    // what was stored), and to the outputs only where they are asked for
    // or the caller needs them.
    let direct = sink.direct && P::all(held);
    let status = |s: BondStatus| P::splat(s as i32 as f64);
    let status = P::select(broken, status(BondStatus::Broken), status(BondStatus::Intact));
    P::for_each_lane_codes(status, loads.mode, |i, [status, mode]| {
        (outs[i].status, outs[i].break_mode) = (status, mode)
    });
    if !direct || sink.outputs {
        scatter3(outs, loads.torque_i, |o: &mut BondOutput| &mut o.torque_i);
        scatter3(outs, loads.torque_j, |o: &mut BondOutput| &mut o.torque_j);
        scatter2(
            outs,
            loads.normal_force,
            loads.sigma,
            |o: &mut BondOutput, [f, s]| (o.normal_force, o.sigma) = (f, s),
        );
        scatter2(outs, loads.tau, loads.delta, |o: &mut BondOutput, [t, d]| {
            (o.tau, o.delta) = (t, d)
        });
        if P::any(broken) {
            loads.mode.for_each_lane(|i, mode| {
                if mode != 0.0 {
                    let o = &mut outs[i];
                    (o.force_i, o.torque_i, o.torque_j) = ([0.0; 3], [0.0; 3], [0.0; 3]);
                }
            });
        }
    }
    if direct {
        add_to_atoms::<P>(sink, first, outs, loads.torque_i, loads.torque_j);
    }
    Some((held, direct))
}

/// The loads of the `P::WIDTH` bonds from bond `first` on added to their
/// atoms, in the order an engine adding the outputs bond by bond gives each
/// atom's sums: the forces lane by lane (owner, then partner; from the
/// outputs, where the step put them as soon as it knew them), then the
/// torques likewise from the lanes (forces and torques lie apart). A ghost
/// partner's rows are looked for only where these lanes have one.
#[inline(always)]
fn add_to_atoms<P: Pack>(
    sink: &LoadSink<'_>,
    first: usize,
    outs: &[BondOutput],
    torque_i: V3<P>,
    torque_j: V3<P>,
) {
    let rows = sink.rows();
    // the lanes' indices read before the first store, which the compiler
    // cannot tell apart from them: they stay in registers
    let mut ends = [[0; 2]; 8];
    for (lane, e) in ends.iter_mut().enumerate().take(P::WIDTH) {
        // SAFETY: the sink was made with the kernel's kinematics, and these
        // bonds are of them.
        *e = unsafe { sink.ends(first + lane) };
    }
    let nlocal = rows.nlocal();
    if sink.route
        && ends
            .iter()
            .take(P::WIDTH)
            .fold(false, |any, e| any | (e[1] >= nlocal))
    {
        add_lanes::<P, true>(rows, &ends, outs, torque_i, torque_j);
    } else {
        add_lanes::<P, false>(rows, &ends, outs, torque_i, torque_j);
    }
}

/// [`add_to_atoms`]'s adds; `ROUTE`: a ghost partner has rows of its own.
#[inline(always)]
fn add_lanes<P: Pack, const ROUTE: bool>(
    rows: &Rows<'_>,
    ends: &[[usize; 2]; 8],
    outs: &[BondOutput],
    torque_i: V3<P>,
    torque_j: V3<P>,
) {
    // SAFETY: the sink checked the indices against the rows; `ROUTE` only
    // where the sink has ghost rows.
    unsafe {
        for (out, &[i, j]) in outs.iter().zip(ends).take(P::WIDTH) {
            let f = Lane3::load(&out.force_i);
            f.add_to(rows.force_of(i));
            f.subtract_from(rows.partner_of::<ROUTE>(j).0);
        }
        let mut owners = [None; 8];
        P::for_each_lane3(torque_i.x, torque_i.y, torque_i.z, |lane, t| {
            owners[lane] = Some(t)
        });
        P::for_each_lane3(torque_j.x, torque_j.y, torque_j.z, |lane, t| {
            let [i, j] = ends[lane];
            if let Some(o) = owners[lane] {
                o.add_to(rows.torque_of(i));
            }
            t.add_to(rows.partner_of::<ROUTE>(j).1);
        });
    }
}

/// The kinematics of a chunk's pairs, read as [`relative`] asks. Each
/// number is added up as it is loaded for the check of the kinematics (a
/// sum that is finite proves every number finite; one that is not sends
/// the chunk to the scalar kernel, which checks exactly); the numbers no
/// law switched on reads are loaded for that alone, a pair of them a load
/// and not moved into their lanes.
struct LaneMotion<P: Pack, F> {
    kin: F,
    sum: P,
    positive: P::Mask,
    velocities: bool,
    spins: bool,
}

impl<P: Pack, F: Fn(usize) -> PairKinematics> LaneMotion<P, F> {
    #[inline(always)]
    fn add(&mut self, v: V3<P>) {
        self.sum = ((self.sum + v.x) + v.y) + v.z;
    }

    /// One 3-vector of each sphere, read from the lanes' pairs and added to
    /// the check's sum, `i`'s first.
    #[inline(always)]
    fn pair_of(
        &mut self,
        of_i: impl Fn(&PairKinematics) -> [f64; 3],
        of_j: impl Fn(&PairKinematics) -> [f64; 3],
    ) -> (V3<P>, V3<P>) {
        let (i, j) = (lanes3(&self.kin, of_i), lanes3(&self.kin, of_j));
        self.add(i);
        self.add(j);
        (i, j)
    }

    /// Whether every number of each pair is finite (per lane; true surely,
    /// false maybe).
    #[inline(always)]
    fn finite(&mut self) -> P::Mask {
        let kin = &self.kin;
        if !self.velocities {
            self.sum = self.sum
                + P::gather2_sum(|lane| [kin(lane).v_i[0], kin(lane).v_i[1]])
                + P::gather2_sum(|lane| [kin(lane).v_i[2], kin(lane).v_j[0]])
                + P::gather2_sum(|lane| [kin(lane).v_j[1], kin(lane).v_j[2]]);
        }
        if !self.spins {
            self.sum = self.sum
                + P::gather2_sum(|lane| [kin(lane).w_i[0], kin(lane).w_i[1]])
                + P::gather2_sum(|lane| [kin(lane).w_i[2], kin(lane).w_j[0]])
                + P::gather2_sum(|lane| [kin(lane).w_j[1], kin(lane).w_j[2]]);
        }
        #[allow(clippy::eq_op)]
        (self.sum - self.sum).ge(P::splat(0.0))
    }
}

impl<P: Pack, F: Fn(usize) -> PairKinematics> MotionSource<P, V3<P>> for LaneMotion<P, F> {
    #[inline(always)]
    fn radii(&mut self) -> (P, P) {
        let kin = &self.kin;
        let (radius_i, radius_j) = P::gather2(|lane| [kin(lane).radius_i, kin(lane).radius_j]);
        let zero = P::splat(0.0);
        self.sum = (self.sum + radius_i) + radius_j;
        self.positive = radius_i.gt(zero) & radius_j.gt(zero);
        (radius_i, radius_j)
    }
    #[inline(always)]
    fn velocities(&mut self) -> (V3<P>, V3<P>) {
        self.velocities = true;
        self.pair_of(|k| k.v_i, |k| k.v_j)
    }
    #[inline(always)]
    fn spins(&mut self) -> (V3<P>, V3<P>) {
        self.spins = true;
        self.pair_of(|k| k.w_i, |k| k.w_j)
    }
}

/// The history of a chunk's bonds, read from and written to their states
/// as [`advance`] asks, one quantity a register; the force goes out as
/// soon as it is known, so that it is not held through the torques' laws
/// (the atoms get it from there). It adds up the slots the step keeps in registers (below `live`) in their order, from the status
/// on, for the results check ([`results_finite_summed`]) as they pass; the
/// slots of a law switched off are read for that alone.
struct Lanes<'a, P, T> {
    states: &'a mut [T],
    outs: &'a mut [BondOutput],
    live: usize,
    sum: P,
    /// The force's components added up, for the results check.
    loads_sum: P,
}

impl<P: Pack, T: BorrowMut<BondState>> Lanes<'_, P, T> {
    #[inline(always)]
    fn add(&mut self, values: &[P]) {
        for &x in values {
            self.sum = self.sum + x;
        }
    }

    #[inline(always)]
    fn add_vector(&mut self, v: V3<P>) {
        self.add(&[v.x, v.y, v.z]);
    }

    /// A vector quantity of the history at `slot`: the new values written
    /// back, or, if the step left it alone but keeps it in registers, read
    /// for the results check; added up either way.
    #[inline(always)]
    fn put_vector(
        &mut self,
        new: Option<V3<P>>,
        slot: usize,
        read: impl Fn(&BondState) -> [f64; 3],
        write: impl Fn(&mut BondState) -> &mut [f64; 3],
    ) {
        let v = match new {
            Some(v) => {
                scatter3(self.states, v, write);
                v
            }
            None if slot < self.live => gather3(self.states, read),
            None => return,
        };
        self.add_vector(v);
    }
}

impl<P: Pack, T: BorrowMut<BondState>> HistoryIo<P, V3<P>> for Lanes<'_, P, T> {
    #[inline(always)]
    fn delta_extremes(&mut self) -> (P, P) {
        gather2(self.states, |s: &BondState| [s.delta_max, s.delta_min])
    }
    #[inline(always)]
    fn shear_force(&mut self) -> V3<P> {
        gather3(self.states, |s: &BondState| s.shear_force)
    }
    #[inline(always)]
    fn twist_angle(&mut self) -> V3<P> {
        gather3(self.states, |s: &BondState| s.twist_angle)
    }
    #[inline(always)]
    fn bend_angle(&mut self) -> V3<P> {
        gather3(self.states, |s: &BondState| s.bend_angle)
    }
    #[inline(always)]
    fn twist_extremes(&mut self) -> TwistHistory<P> {
        let (max, min) = gather2(self.states, |s: &BondState| [s.twist_max, s.twist_min]);
        TwistHistory { max, min }
    }
    #[inline(always)]
    fn bend_history(&mut self) -> BendHistory<P, V3<P>> {
        BendHistory {
            leading: gather3(self.states, |s: &BondState| s.bend_history),
            opposite: gather(self.states, |s: &BondState| s.bend_opposite),
        }
    }
    #[inline(always)]
    fn put_delta_extremes(&mut self, new: Option<(P, P)>) {
        let (max, min) = match new {
            Some((max, min)) => {
                scatter2(self.states, max, min, |s: &mut BondState, [hi, lo]| {
                    (s.delta_max, s.delta_min) = (hi, lo)
                });
                (max, min)
            }
            None => self.delta_extremes(),
        };
        self.add(&[max, min]);
    }
    #[inline(always)]
    fn put_shear_force(&mut self, new: Option<V3<P>>) {
        self.put_vector(new, SHEAR_FORCE, |s| s.shear_force, |s| &mut s.shear_force);
    }
    #[inline(always)]
    fn put_twist_angle(&mut self, new: Option<V3<P>>) {
        self.put_vector(new, TWIST_ANGLE, |s| s.twist_angle, |s| &mut s.twist_angle);
    }
    #[inline(always)]
    fn put_bend_angle(&mut self, new: Option<V3<P>>) {
        self.put_vector(new, BEND_ANGLE, |s| s.bend_angle, |s| &mut s.bend_angle);
    }
    #[inline(always)]
    fn put_twist_extremes(&mut self, new: Option<TwistHistory<P>>) {
        let t = match new {
            Some(t) => {
                scatter2(self.states, t.max, t.min, |s: &mut BondState, [max, min]| {
                    (s.twist_max, s.twist_min) = (max, min)
                });
                t
            }
            None if TWIST_MAX < self.live => self.twist_extremes(),
            None => return,
        };
        self.add(&[t.max, t.min]);
    }
    #[inline(always)]
    fn put_bend_history(&mut self, new: Option<BendHistory<P, V3<P>>>) {
        let b = match new {
            Some(b) => {
                scatter3(self.states, b.leading, |s: &mut BondState| &mut s.bend_history);
                scatter(self.states, b.opposite, |s: &mut BondState, x| {
                    s.bend_opposite = x
                });
                b
            }
            None if BEND_HISTORY < self.live => self.bend_history(),
            None => return,
        };
        self.add_vector(b.leading);
        self.add(&[b.opposite]);
    }
    #[inline(always)]
    fn put_force(&mut self, f: V3<P>) {
        scatter3(self.outs, f, |o: &mut BondOutput| &mut o.force_i);
        self.loads_sum = (f.x + f.y) + f.z;
    }
}

/// How many slots, from the first, a step with these laws switched on
/// keeps in registers: up to the last one it changes. The rest, which it
/// leaves alone, only the results check reads, from memory (at least a
/// register's worth a bond, as it reads them a register at a time).
#[inline(always)]
fn live_slots(shear: bool, twist: bool, bend: bool) -> usize {
    if bend {
        BOND_STATE_LEN
    } else if twist {
        TWIST_MIN + 1
    } else if shear {
        SHEAR_FORCE + 3
    } else {
        SHEAR_FORCE
    }
}

const SHEAR_FORCE: usize = slot_of!(shear_force);
const TWIST_ANGLE: usize = slot_of!(twist_angle);
const BEND_ANGLE: usize = slot_of!(bend_angle);
const TWIST_MAX: usize = slot_of!(twist_max);
const TWIST_MIN: usize = slot_of!(twist_min);
const BEND_HISTORY: usize = slot_of!(bend_history);

/// One quantity of `P::WIDTH` items, lane `i` from `items[i]`.
#[inline(always)]
fn gather<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> f64) -> P {
    P::gather(|i| f(items[i].borrow()))
}

/// [`gather`] of two quantities, next to each other in memory.
#[inline(always)]
fn gather2<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> [f64; 2]) -> (P, P) {
    P::gather2(|i| f(items[i].borrow()))
}

/// [`gather`] of a vector quantity.
#[inline(always)]
fn gather3<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    lanes3(|i| items[i].borrow(), |t| f(t))
}

/// A vector quantity of `P::WIDTH` items, lane `i` from `item(i)`.
#[inline(always)]
fn lanes3<T, P: Pack>(item: impl Fn(usize) -> T, f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    let (x, y) = P::gather2(|i| {
        let v = f(&item(i));
        [v[0], v[1]]
    });
    V3::new(x, y, P::gather(|i| f(&item(i))[2]))
}

/// Lane `i` of `v` into `items[i]`.
#[inline(always)]
fn scatter<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], v: P, mut f: impl FnMut(&mut T, f64)) {
    v.for_each_lane(|i, x| f(items[i].borrow_mut(), x));
}

/// [`scatter`] of two quantities.
#[inline(always)]
fn scatter2<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], a: P, b: P, mut f: impl FnMut(&mut T, [f64; 2])) {
    P::for_each_lane2(a, b, |i, pair| f(items[i].borrow_mut(), pair));
}

/// [`scatter`] of a vector quantity.
#[inline(always)]
fn scatter3<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], v: V3<P>, f: impl Fn(&mut T) -> &mut [f64; 3]) {
    P::for_each_lane2(v.x, v.y, |i, [x, y]| {
        let v = f(items[i].borrow_mut());
        (v[0], v[1]) = (x, y)
    });
    v.z.for_each_lane(|i, z| f(items[i].borrow_mut())[2] = z);
}
