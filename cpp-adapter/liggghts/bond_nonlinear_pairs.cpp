// cohesion bond/nonlinear's pair bonds: the core's bond store (bonds_fix.h)
// linked after every list build, its chunks stepped and their loads added
// to the atoms, the bonds that break taken out of the pair loop, those that
// form put in, the view sent round where either happened on any rank, the
// counts, and the store's check. Every rule is the core's; this file finds
// the pairs in the engine's lists and adds the loads.
#include "bond_ledger.h"
#include "bond_nonlinear_cohesion.h"
#include "bonds_fix.h"
#include "core_bridge.h"
#include "core_message.h"
#include "store_check.h"
#include "store_pass.h"

#include "fix_property_atom.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

GbBondStore *BondNonlinearCohesion::bondStore() const { return bonds_ ? bonds_->store() : nullptr; }

bool BondNonlinearCohesion::storeCurrent() const
{
    return passStep_ == update->ntimestep && passAtoms_ == static_cast<bigint>(atom->nlocal) + atom->nghost;
}

void BondNonlinearCohesion::energyTerms(double out[kEnergyTerms]) const
{
    for (int k = 0; k < kEnergyTerms; k++) out[k] = 0.0;
    GbBondStore *store = bondStore();
    if (!store) return;
    const GbAtomArrays arrays = atomArraysOf(atom);
    GbEnergySums e;
    if (granbond_bond_store_stored_energy(store, parameters_.table(), kinds_.size(), &arrays, &out[0]) != GB_STATUS_OK ||
        granbond_bond_store_energy_sums(store, &e) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: the bonds' energy: " + coreReason());
    out[1] = e.damping;
    out[2] = e.hysteresis;
    out[3] = e.released;
}

void BondNonlinearCohesion::bondEnergy(size_t k, double *out) const
{
    const GbAtomArrays arrays = atomArraysOf(atom);
    if (granbond_bond_store_bond_energy(bondStore(), parameters_.table(), kinds_.size(), &arrays, k, out) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: a bond's energy: " + coreReason());
}

void BondNonlinearCohesion::addDissipatedShares()
{
    const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
    shares_.assign(6 * static_cast<size_t>(nall), 0.0);
    if (granbond_bond_store_add_dissipated_shares(bonds_->store(), parameters_.table(), kinds_.size(), shares_.data(),
                                                  static_cast<size_t>(nall), 6, 0) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: computeDissipatedEnergy: " + coreReason());
    double **table = dissipated_->array_atom;
    for (int i = 0; i < nlocal; i++)
        for (int c = 0; c < 6; c++) table[i][1 + c] += shares_[6 * static_cast<size_t>(i) + c];
    // a bond's partner on another rank (or a periodic image) gets its
    // share at its owner, through the store's fix
    double *ghosts = bonds_->ghostLoads();
    std::copy(shares_.begin() + 6 * static_cast<size_t>(nlocal), shares_.end(), ghosts);
    bonds_->returnGhostShares(nlocal > 0 ? table[0] : nullptr, 7, 1);
}

void BondNonlinearCohesion::failPair(int i, int j, const char *what)
{
    endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: " + std::string(what) + " of atoms " +
                                     std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
                                     std::to_string(static_cast<long long>(atom->tag[j])) + " at step " +
                                     std::to_string(static_cast<long long>(update->ntimestep)) + ": " + coreReason());
}

// After a list build (and at a run's start): every bond finds its atoms
// again (the losses counted and told with their cause), the view reaches
// the ghosts, and the pairs' flags are marked from the store.
void BondNonlinearCohesion::linkBonds()
{
    linkedAt_ = neighbor->ncalls;
    GbLinkReport report;
    // the ghost atoms' reach (LIGGGHTS's Comm::setup)
    if (linkStore(bonds_->store(), atom, kinds_, parameters_.ntypes(),
                  std::max(neighbor->cutneighmax, comm->cutghostuser), report) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: finding the bonds' atoms: " + coreReason());
    const std::string lost = linkLosses(GRANBOND_NOTICE_PAIRS_LOST_LIGGGHTS, report, update->ntimestep, world);
    if (!lost.empty() && comm->me == 0 && !warnedLost_) {
        warnedLost_ = true;
        error->warning(FLERR, lost.c_str());
    }
    bonds_->sendView();
    markBonded();
}

// The flags of the listed pairs from the store and its view: the bit set
// where a bond is, cleared where none is (a bond that broke or was lost).
void BondNonlinearCohesion::markBonded()
{
    const LAMMPS_NS::NeighList *list = pair_->list, *history = pair_->listgranhistory;
    if (!list || !history || !history->firstneigh) return;
    GbBondStore *store = bonds_->store();
    const GbAtomIds ids = atomIdsOf(atom);
    const int ntypes1 = parameters_.ntypes() + 1;
    const int *type = atom->type;
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        int *flags = history->firstneigh[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            const bool bonded = kinds_[static_cast<size_t>(type[i]) * ntypes1 + type[j]] >= 0 &&
                                granbond_bond_store_bonded(store, static_cast<size_t>(i), static_cast<size_t>(j), &ids);
            if (bonded)
                flags[jj] |= kBondedFlag;
            else
                flags[jj] &= ~kBondedFlag;
        }
    }
}

// Steps the bonds of the pass not stepped yet; the core adds their loads to
// the atoms as the engine's pair loop would (each atom's relaxation factor;
// a ghost partner's loads in the fix's rows under newton off), and the
// virial of each bond is tallied once. Whether the virial is wanted, where
// a ghost's loads go and whether any atom's factor differs from 1 are
// decided once a pass, not once a bond.
void BondNonlinearCohesion::stepBonds(bool advance)
{
    const double *const x0 = atom->x[0];
    const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
    LAMMPS_NS::PairGran *const pair = pair_;
    // (Debian's LIGGGHTS: every factor is the constant 1, and this test
    // compiles away)
    bool unitRelax = true;
    for (int i = 0; i < nall; i++) unitRelax &= pair->relax(i) == 1.0;
    if (!unitRelax) {
        relax_.resize(static_cast<size_t>(nall));
        for (int i = 0; i < nall; i++) relax_[static_cast<size_t>(i)] = pair->relax(i);
    }
    const bool ghostRows = force->newton_pair == 0 && atom->nghost > 0;
    const GbAtomLoads loads = atomLoadsOf(atom, ghostRows ? ghostLoads_ : nullptr, unitRelax ? nullptr : relax_.data());
    const auto failed = [&](int i, int j, const std::string &why) {
        if (i >= 0) failPair(i, j, "the bond");
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: the bonds: " + why);
    };
    std::vector<GbBondOutput> *const kept = bondOutputUsers > 0 && advance ? &outputs_ : nullptr;
    stepStoreChunks(bonds_->store(), parameters_.table(), kinds_.size(), atom, atomIdsOf(atom), loads, kept,
                    pair_->evflag != 0,
                    [=](int i, int j, const GbBondOutput &o) {
                        const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
                        // each bond is stepped on one rank: its whole virial here
                        pair->ev_tally_xyz(i, j, nlocal, 1, 0.0, 0.0, o.force_i[0], o.force_i[1], o.force_i[2],
                                           xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
                    },
                    failed);
}

// The bonds that broke in the pass so far: their pairs leave the bonded
// flag (the contact models act on them again), the break log gets them;
// then, where any rank broke a bond, the view goes round again and the
// flags follow it.
void BondNonlinearCohesion::takeBroken(bool advance)
{
    GbBondStore *store = bonds_->store();
    const size_t nb = granbond_bond_store_broken_count(store);
    for (size_t m = 0; m < nb && advance && book_->logging(); m++) {
        GbBrokenBond b;
        if (granbond_bond_store_broken(store, m, &b) != GB_STATUS_OK)
            endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: " + coreReason());
        const int i = b.ends[0], j = b.ends[1];
        BreakEvent e;
        if (makeBreakEvent(parameters_.model(atom->type[i], atom->type[j]), b.out, atom, i, j,
                           static_cast<double>(update->ntimestep), e) != GB_STATUS_OK)
            failPair(i, j, "the break log's event");
        book_->record(e);
    }
    if (bonds_->viewAfterBreaks(nb > 0)) markBonded();
}

// A pair within reach at a creation step, or of one `bonded yes` clump:
// bonded if the core says so, by this rank (its owner is local here) or by
// the rank that owns it (newton off: both list the pair).
bool BondNonlinearCohesion::pairBonds(SurfacesCloseData &d)
{
    const int i = d.i, j = d.j;
    const int32_t kind = kinds_[static_cast<size_t>(d.itype) * (parameters_.ntypes() + 1) + d.jtype];
    if (kind < 0) return false;
    // spheres of one `bonded yes` clump, in the first force pass after
    // their insertion (the id is the insertion step plus a fraction)
    const double *clump = clumpIds_ ? clumpIds_->vector_atom : 0;
    const bool clumped = clump && clump[i] >= 0.0 && clump[i] == clump[j] &&
                         static_cast<double>(update->ntimestep) < clump[i];
    if (!createsNow_[static_cast<size_t>(kind)] && !clumped) return false;
    if (d.rsq == 0.0) coincident(d);
    bool made = false;
    if (proposePair(bonds_->store(), parameters_.table()[kind], static_cast<uint16_t>(kind), atom, i, j,
                    !force->newton_pair, update->ntimestep, clumped, made, formedThisPass_) != GB_STATUS_OK)
        failPair(i, j, "the bond's creation");
    if (!made) return false;
    if (d.contact_flags) *d.contact_flags |= kBondedFlag;
    return true;
}

// The contact models have no normal to work with (the engine's would give
// nan), nor has a bond: stop, as the core does in LAMMPS.
void BondNonlinearCohesion::coincident(const SurfacesCloseData &d)
{
    endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: atoms " + std::to_string(static_cast<long>(atom->tag[d.i])) +
                                     " and " + std::to_string(static_cast<long>(atom->tag[d.j])) + " at step " +
                                     std::to_string(static_cast<long long>(update->ntimestep)) +
                                     ": coincident centres: the pair has no axis; place the atoms apart");
}

// The pass's end: the bonds formed in it stepped too, those broken out of
// the store, the ghosts' loads home (newton off), the view sent again where
// any rank formed a bond, the counts.
void BondNonlinearCohesion::finishPairPass()
{
    stepBonds(advance_);
    bonds_->finishPass(formedThisPass_, !force->newton_pair, bondOutputUsers > 0 && advance_ ? &outputs_ : nullptr);
    if (advance_ && dissipated_) addDissipatedShares();
    formedThisPass_ = false;
    countPairs();
    if (checkStore_) checkStore();
    passStep_ = update->ntimestep;
    passAtoms_ = static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// compute bond/counter's pair values: this rank's counts of the store.
void BondNonlinearCohesion::countPairs()
{
    const GbStoreCounts c = bonds_->counts();
    book_->beginPassIfNew(tally_, update);
    tally_.take(c);
}

// GRANBOND_CHECK_STORE: after a pass, the bonds recounted against the
// engine's atoms: every pair of the lists flagged bonded exactly when the
// store or its view holds its bond; each bond stored once over all ranks,
// between an owner that is local and a partner with the id it names; and
// created = broken + intact + lost over all ranks. A mismatch ends the run.
void BondNonlinearCohesion::checkStore()
{
    GbBondStore *store = bonds_->store();
    const GbAtomIds ids = atomIdsOf(atom);
    const LAMMPS_NS::NeighList *list = pair_->list, *history = pair_->listgranhistory;
    std::string wrong;
    for (int ii = 0; list && history && ii < list->inum && wrong.empty(); ii++) {
        const int i = list->ilist[ii];
        for (int jj = 0; jj < list->numneigh[i] && wrong.empty(); jj++)
            wrong = flagFinding(store, i, list->firstneigh[i][jj] & NEIGHMASK, ids,
                                (history->firstneigh[i][jj] & kBondedFlag) != 0);
    }
    const std::string rest = checkStoredBonds(store, ids, atom->nlocal, world);
    if (wrong.empty()) wrong = rest;
    int bad = !wrong.empty(), anyBad = 0;
    MPI_Allreduce(&bad, &anyBad, 1, MPI_INT, MPI_MAX, world);
    if (bad)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: store check at step " +
                                         std::to_string(static_cast<long long>(update->ntimestep)) + ": " + wrong);
    if (anyBad) endRun(error, FLERR, "cohesion bond/nonlinear: store check failed on another rank");
}

}
}
