// pair_style granbond's bonds: the core's bond store (bond_store_fix.h)
// linked after every list build, its chunks stepped and their loads added
// to the atoms, the bonds that break taken out of the contact loop, those
// that form put in, the view sent round where either happened on any rank,
// the counts, and the store's check. Every rule is the core's; this file
// finds the pairs in the engine's lists and adds the loads.
#include "pair_granbond.h"
#include "bond_store_fix.h"
#include "core_message.h"
#include "bond_ledger.h"
#include "store_check.h"
#include "atom_loads.h"
#include "store_pass.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

GbAtomIds PairGranbond::atomIds() const { return atomIdsOf(atom); }

GbAtomArrays PairGranbond::atomArrays() const { return atomArraysOf(atom); }

GbBondStore *PairGranbond::bondStore() const { return bonds_ ? bonds_->store() : nullptr; }

size_t PairGranbond::bondKind(int i, int j, size_t) const
{
    const int ti = atom->type[i], tj = atom->type[j];
    return static_cast<size_t>(std::min(ti, tj)) * (atom->ntypes + 1) + std::max(ti, tj);
}

bool PairGranbond::storeCurrent() const
{
    return passStep_ == update->ntimestep && passAtoms_ == static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// After a list build: every bond finds its atoms again (the losses counted
// and told with their cause), the view reaches the ghosts, and the contact
// history's flags are marked from the store.
void PairGranbond::linkBonds()
{
    GbLinkReport report;
    if (linkStore(bonds_->store(), atom, kinds_, atom->ntypes, comm->cutghostuser, report) != GB_STATUS_OK)
        error->one(FLERR, "pair granbond: finding the bonds' atoms: " + coreReason());
    const std::string lost = linkLosses(GRANBOND_NOTICE_PAIRS_LOST_LAMMPS, report, update->ntimestep, world);
    if (!lost.empty() && comm->me == 0) error->warning(FLERR, lost);
    bonds_->sendView();
    markBonded();
}

// The flags of the listed pairs from the store and its view: bonded, or
// not any more (a bond that broke or was lost: its contact starts afresh,
// unless it went on under the bond).
void PairGranbond::markBonded()
{
    GbBondStore *store = bonds_->store();
    const GbAtomIds ids = atomIds();
    const int ntypes1 = atom->ntypes + 1;
    const int *type = atom->type;
    livePairs_.assign(static_cast<size_t>(list->inum), 0);
    listPosition_.assign(static_cast<size_t>(atom->nlocal), -1);
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        int *touch = fixHistory_->firstflag[i];
        double *allhistory = fixHistory_->firstvalue[i];
        listPosition_[i] = ii;
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            const size_t tp = static_cast<size_t>(std::min(type[i], type[j])) * ntypes1 + std::max(type[i], type[j]);
            if (bond_[tp] &&
                granbond_bond_store_bonded(store, static_cast<size_t>(i), static_cast<size_t>(j), &ids)) {
                touch[jj] = kBondedMark;
                continue;
            }
            livePairs_[ii]++;
            if (touch[jj] == kBondedMark) {
                touch[jj] = 0;
                if (!pairs_[tp].bond.contact_under_bond)
                    std::fill(allhistory + sizeHistory_ * jj, allhistory + sizeHistory_ * (jj + 1), 0.0);
            }
        }
    }
}

// Steps the bonds of the pass not stepped yet and adds their loads to the
// atoms: both atoms' forces and torques (a ghost's for the engine's reverse
// communication under newton on, else for the fix's), the virial of each
// bond once.
void PairGranbond::stepBonds(bool advance)
{
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;
    const int nlocal = atom->nlocal;
    stepChunks(
        atom, bonds_->store(), bond_, force->newton_pair != 0, ghostLoads_,
        bondOutputUsers > 0 && advance ? &outputs_ : nullptr, evflag != 0,
        [this, x0, nlocal](int i, int j, const double *f) {
            const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
            // each bond is stepped on one rank: its whole virial here
            ev_tally_xyz(i, j, nlocal, 1, 0.0, 0.0, f[0], f[1], f[2], xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
        },
        [&](int i, int j, const std::string &why) {
            if (i >= 0) failPair(i, j, "the bond");
            error->one(FLERR, "pair granbond: the bonds: " + why);
        });
}

// The bonds that broke in the pass so far: their pairs leave the bonded
// flag (the contact starts afresh, unless it went on under the bond), the
// break log gets them; then, where any rank broke a bond, the view goes
// round again and the flags follow it.
void PairGranbond::takeBroken(bool advance)
{
    GbBondStore *store = bonds_->store();
    const size_t nb = granbond_bond_store_broken_count(store);
    const int nlocal = atom->nlocal;
    const int ntypes1 = atom->ntypes + 1;
    for (size_t m = 0; m < nb; m++) {
        GbBrokenBond b;
        if (granbond_bond_store_broken(store, m, &b) != GB_STATUS_OK) error->one(FLERR, "pair granbond: " + coreReason());
        const int i = b.ends[0], j = b.ends[1];
        const size_t tp =
            static_cast<size_t>(std::min(atom->type[i], atom->type[j])) * ntypes1 + std::max(atom->type[i], atom->type[j]);
        // the pair in the list: under i, or under j where j is local
        for (int side = 0; side < 2; side++) {
            const int a = side ? j : i, other = side ? i : j;
            if (a >= nlocal) continue;
            const int *jlist = list->firstneigh[a];
            int *touch = fixHistory_->firstflag[a];
            for (int jj = 0; jj < list->numneigh[a]; jj++)
                if ((jlist[jj] & NEIGHMASK) == other && touch[jj] == kBondedMark) {
                    touch[jj] = 0;
                    if (static_cast<size_t>(a) < listPosition_.size() && listPosition_[a] >= 0)
                        livePairs_[listPosition_[a]]++;
                    if (!pairs_[tp].bond.contact_under_bond) {
                        double *h = fixHistory_->firstvalue[a] + sizeHistory_ * jj;
                        std::fill(h, h + sizeHistory_, 0.0);
                    }
                }
        }
        if (breakLogUsers > 0 && advance) {
            BreakEvent e;
            if (makeBreakEvent(bond_[tp], b.out, atom, i, j, static_cast<double>(update->ntimestep), e) != GB_STATUS_OK)
                failPair(i, j, "the break log's event");
            breaks_.push_back(e);
        }
    }
    if (bonds_->viewAfterBreaks(nb > 0)) markBonded();
}

// A pair within the creation rules at a creation step: bonded if the core
// says so, by this rank (the pair's owner is local here) or by the rank
// that owns it (newton off: both list the pair). Returns whether it is a
// bond now.
bool PairGranbond::tryBond(size_t tp, int i, int j, int *touch, double *history)
{
    bool made = false;
    if (proposePair(bonds_->store(), bond_[tp], static_cast<uint16_t>(tp), atom, i, j, !force->newton_pair,
                    update->ntimestep, false, made, formedThisPass_) != GB_STATUS_OK)
        failPair(i, j, "the bond's creation");
    if (!made) return false;
    *touch = kBondedMark;
    if (!pairs_[tp].bond.contact_under_bond) std::fill(history, history + sizeHistory_, 0.0);
    return true;
}

// compute pair granbond's values: this rank's counts (the compute sums
// them over the ranks).
void PairGranbond::countBonds()
{
    const GbStoreCounts c = bonds_->counts();
    granbond_store_counts_row(&c, pvector);
    GbEnergySums e;
    if (granbond_bond_store_energy_sums(bonds_->store(), &e) != GB_STATUS_OK)
        error->one(FLERR, "pair granbond: " + coreReason());
    pvector[8] = e.damping;
    pvector[9] = e.hysteresis;
    pvector[10] = e.released;
}

// GRANBOND_CHECK_STORE: after a pass, the bonds recounted against the
// engine's atoms: every pair of the lists flagged bonded exactly when the
// store or its view holds its bond; each bond stored once over all ranks,
// between an owner that is local and a partner with the id it names; and
// created = broken + intact + lost over all ranks. A mismatch ends the run.
void PairGranbond::checkStore()
{
    GbBondStore *store = bonds_->store();
    const GbAtomIds ids = atomIds();
    std::string wrong;
    for (int ii = 0; ii < list->inum && wrong.empty(); ii++) {
        const int i = list->ilist[ii];
        for (int jj = 0; jj < list->numneigh[i] && wrong.empty(); jj++)
            wrong = flagFinding(store, i, list->firstneigh[i][jj] & NEIGHMASK, ids,
                                fixHistory_->firstflag[i][jj] == kBondedMark);
    }
    const std::string rest = checkStoredBonds(store, ids, atom->nlocal, world);
    if (wrong.empty()) wrong = rest;
    int bad = !wrong.empty(), anyBad = 0;
    MPI_Allreduce(&bad, &anyBad, 1, MPI_INT, MPI_MAX, world);
    if (bad) error->one(FLERR, "pair granbond: store check at step " + std::to_string(update->ntimestep) + ": " + wrong);
    if (anyBad) error->all(FLERR, "pair granbond: store check failed on another rank");
}

// Whether a bond exists on any rank; collective.
bool PairGranbond::bondsExist() const
{
    int mine = bonds_ && granbond_bond_store_len(bonds_->store()) > 0, any = 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    return any != 0;
}

}
}
