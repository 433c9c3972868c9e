// pair_style granbond's bonds: the core's bond store (bond_store_fix.h)
// linked after every list build, its chunks stepped and their loads added
// to the atoms, the bonds that break taken out of the contact loop, those
// that form put in, the view sent round where either happened on any rank,
// the counts, and the store's check. Every rule is the core's; this file
// finds the pairs in the engine's lists and adds the loads.
#include "pair_granbond.h"
#include "bond_store_fix.h"
#include "core_message.h"
#include "vector_adds.h"

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

GbAtomArrays PairGranbond::atomArrays() const
{
    const bool any = atom->nmax > 0;
    GbAtomArrays a;
    a.x = any ? atom->x[0] : nullptr;
    a.v = any ? atom->v[0] : nullptr;
    a.omega = any ? atom->omega[0] : nullptr;
    a.radius = atom->radius;
    a.count = static_cast<size_t>(atom->nlocal + atom->nghost);
    return a;
}

GbBondStore *PairGranbond::bondStore() const { return bonds_ ? bonds_->store() : nullptr; }

bool PairGranbond::storeCurrent() const
{
    return passStep_ == update->ntimestep && passAtoms_ == static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// After a list build: every bond finds its atoms again (the losses counted
// and told with their cause), the view reaches the ghosts, and the contact
// history's flags are marked from the store.
void PairGranbond::linkBonds()
{
    GbStoreAtoms sa;
    sa.ids = atomIds();
    sa.nlocal = static_cast<size_t>(atom->nlocal);
    sa.x = atom->nmax > 0 ? atom->x[0] : nullptr;
    sa.types = atom->type;
    sa.reach = comm->cutghostuser;
    GbLinkReport report;
    if (granbond_bond_store_link(bonds_->store(), &sa, kinds_.data(), static_cast<size_t>(atom->ntypes), &report) !=
        GB_STATUS_OK)
        error->one(FLERR, "pair granbond: finding the bonds' atoms: " + coreReason());
    const long long mine[4] = {report.owner_gone, report.partner_unreached, report.id_reused, report.no_model};
    long long all[4];
    MPI_Allreduce(mine, all, 4, MPI_LONG_LONG, MPI_SUM, world);
    const long long lost = all[0] + all[1] + all[2] + all[3];
    if (lost > 0 && comm->me == 0) {
        std::string causes;
        const char *const why[4] = {
            "their atom left the system (deleted, or lost through a boundary)",
            "their partner was not among the atoms within the communication cutoff (deleted, lost, or moved "
            "farther than the bond's reach between runs)",
            "an atom's id was taken over by a new atom",
            "their atoms' types have no bond model any more (set type, or pair_coeff without bond/nonlinear)"};
        for (int c = 0; c < 4; c++)
            if (all[c] > 0) causes += (causes.empty() ? "" : "; ") + std::to_string(all[c]) + " because " + why[c];
        error->warning(FLERR, "pair granbond (bond/nonlinear): " + std::to_string(lost) + " bonds lost at step " +
                                  std::to_string(static_cast<long long>(update->ntimestep)) +
                                  " without breaking: " + causes +
                                  " (counted in compute pair granbond's 8th value)");
    }
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
                if (!pairs_[tp].contactUnderBond)
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
    GbBondStore *store = bonds_->store();
    const GbAtomArrays arrays = atomArrays();
    const GbAtomIds ids = atomIds();
    int32_t ends[2 * GRANBOND_BOND_STORE_CHUNK];
    GbBondOutput outs[GRANBOND_BOND_STORE_CHUNK];
    double *const f0 = atom->f[0], *const t0 = atom->torque[0];
    const double *const x0 = atom->x[0];
    const int nlocal = atom->nlocal;
    for (;;) {
        size_t n = 0, bad = 0;
        if (granbond_bond_store_step_next(store, bond_.data(), bond_.size(), &arrays, &ids, ends, outs, &n, &bad) !=
            GB_STATUS_OK) {
            int32_t e[2] = {-1, -1};
            int64_t partner = 0;
            double state[GRANBOND_BOND_STATE_LEN];
            const std::string why = coreReason();
            if (granbond_bond_store_bond(store, bad, e, &partner, state) == GB_STATUS_OK && e[0] >= 0)
                failPair(e[0], e[1], "the bond");
            error->one(FLERR, "pair granbond: the bonds: " + why);
        }
        if (n == 0) break;
        for (size_t k = 0; k < n; k++) {
            const int i = ends[2 * k], j = ends[2 * k + 1];
            const GbBondOutput &o = outs[k];
            add3(f0 + 3 * static_cast<size_t>(i), o.force_i);
            add3(t0 + 3 * static_cast<size_t>(i), o.torque_i);
            if (j < nlocal || force->newton_pair) {
                subtract3(f0 + 3 * static_cast<size_t>(j), o.force_i);
                add3(t0 + 3 * static_cast<size_t>(j), o.torque_j);
            } else {
                double *g = ghostLoads_ + 6 * static_cast<size_t>(j - nlocal);
                subtract3(g, o.force_i);
                add3(g + 3, o.torque_j);
            }
            if (evflag) {
                const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
                // each bond is stepped on one rank: its whole virial here
                ev_tally_xyz(i, j, nlocal, 1, 0.0, 0.0, o.force_i[0], o.force_i[1], o.force_i[2], xi[0] - xj[0],
                             xi[1] - xj[1], xi[2] - xj[2]);
            }
        }
        if (bondOutputUsers > 0 && advance) outputs_.insert(outputs_.end(), outs, outs + n);
    }
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
                    if (!pairs_[tp].contactUnderBond) {
                        double *h = fixHistory_->firstvalue[a] + sizeHistory_ * jj;
                        std::fill(h, h + sizeHistory_, 0.0);
                    }
                }
        }
        if (breakLogUsers > 0 && advance) {
            BreakEvent e;
            const int lo = atom->tag[i] < atom->tag[j] ? i : j, hi = lo == i ? j : i;
            if (makeBreakEvent(bond_[tp], b.out, atom->x[lo], atom->x[hi], atom->radius[lo], atom->radius[hi],
                               static_cast<double>(atom->tag[lo]), static_cast<double>(atom->tag[hi]),
                               static_cast<double>(update->ntimestep), e) != GB_STATUS_OK)
                failPair(i, j, "the break log's event");
            breaks_.push_back(e);
        }
    }
    int mine = nb > 0, any = 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any) {
        bonds_->sendView();
        markBonded();
    }
}

// A pair within the creation rules at a creation step: bonded if the core
// says so, by this rank (the pair's owner is local here) or by the rank
// that owns it (newton off: both list the pair). Returns whether it is a
// bond now.
bool PairGranbond::tryBond(size_t tp, int i, int j, int *touch, double *history)
{
    GbBondStore *store = bonds_->store();
    const tagint *tag = atom->tag;
    const int nlocal = atom->nlocal;
    const int owner = granbond_bond_store_creates_here(i < nlocal, j < nlocal, tag[i], tag[j], !force->newton_pair);
    GbPairKinematics k;
    int32_t made = 0;
    if (owner < 0) {
        pairKinematics(i, j, k);
        if (granbond_bond_store_would_create(store, bond_[tp], static_cast<size_t>(i), static_cast<size_t>(j), &k,
                                             update->ntimestep, &made) != GB_STATUS_OK)
            failPair(i, j, "the bond's creation");
    } else {
        const int o = owner == 0 ? i : j, p = owner == 0 ? j : i;
        pairKinematics(o, p, k);
        if (granbond_bond_store_try_create(store, bond_[tp], static_cast<uint16_t>(tp), static_cast<size_t>(o),
                                           static_cast<size_t>(p), tag[o], tag[p], &k, update->ntimestep,
                                           &made) != GB_STATUS_OK)
            failPair(i, j, "the bond's creation");
        if (made) formedThisPass_ = true;
    }
    if (!made) return false;
    *touch = kBondedMark;
    if (!pairs_[tp].contactUnderBond) std::fill(history, history + sizeHistory_, 0.0);
    return true;
}

// compute pair granbond's values: this rank's counts (the compute sums
// them over the ranks).
void PairGranbond::countBonds()
{
    const GbStoreCounts c = bonds_->counts();
    pvector[0] = static_cast<double>(c.created);
    pvector[1] = static_cast<double>(c.broken_distance + c.broken_tension + c.broken_compression + c.broken_shear);
    pvector[2] = static_cast<double>(c.intact);
    pvector[3] = static_cast<double>(c.broken_distance);
    pvector[4] = static_cast<double>(c.broken_tension);
    pvector[5] = static_cast<double>(c.broken_compression);
    pvector[6] = static_cast<double>(c.broken_shear);
    pvector[7] = static_cast<double>(c.lost_owner_gone + c.lost_partner_unreached + c.lost_id_reused + c.lost_no_model);
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
        for (int jj = 0; jj < list->numneigh[i] && wrong.empty(); jj++) {
            const int j = list->firstneigh[i][jj] & NEIGHMASK;
            const bool flagged = fixHistory_->firstflag[i][jj] == kBondedMark;
            const bool bonded = granbond_bond_store_bonded(store, static_cast<size_t>(i), static_cast<size_t>(j), &ids);
            if (flagged != bonded)
                wrong = "the pair of atoms " + std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
                        std::to_string(static_cast<long long>(atom->tag[j])) + (flagged ? " is flagged bonded, but no bond" : " is bonded, but not flagged");
        }
    }
    const size_t n = granbond_bond_store_len(store);
    std::vector<double> mine;
    for (size_t k = 0; k < n && wrong.empty(); k++) {
        int32_t e[2];
        int64_t partner = 0;
        double state[GRANBOND_BOND_STATE_LEN];
        if (granbond_bond_store_bond(store, k, e, &partner, state) != GB_STATUS_OK)
            wrong = "bond " + std::to_string(k) + ": " + coreReason();
        else if (e[0] < 0 || e[0] >= atom->nlocal || e[1] < 0 || static_cast<int64_t>(atom->tag[e[1]]) != partner)
            wrong = "bond " + std::to_string(k) + " does not join its owner and its partner " + std::to_string(partner);
        else {
            const double a = static_cast<double>(atom->tag[e[0]]), b = static_cast<double>(partner);
            mine.push_back(std::min(a, b));
            mine.push_back(std::max(a, b));
        }
    }
    // every bond once: the pairs of all ranks, gathered
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(comm->nprocs), offsets(comm->nprocs + 1, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int r = 0; r < comm->nprocs; r++) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(static_cast<size_t>(offsets[comm->nprocs]));
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
    std::vector<std::pair<double, double>> pairs;
    for (size_t k = 0; k + 1 < all.size(); k += 2) pairs.emplace_back(all[k], all[k + 1]);
    std::sort(pairs.begin(), pairs.end());
    for (size_t k = 1; k < pairs.size() && wrong.empty(); k++)
        if (pairs[k] == pairs[k - 1])
            wrong = "the bond of atoms " + std::to_string(static_cast<long long>(pairs[k].first)) + " and " +
                    std::to_string(static_cast<long long>(pairs[k].second)) + " is stored twice";
    const GbStoreCounts c = bonds_->counts();
    const long long local[4] = {c.created, c.broken_distance + c.broken_tension + c.broken_compression + c.broken_shear,
                                c.intact, c.lost_owner_gone + c.lost_partner_unreached + c.lost_id_reused + c.lost_no_model};
    long long sums[4];
    MPI_Allreduce(local, sums, 4, MPI_LONG_LONG, MPI_SUM, world);
    if (wrong.empty() && sums[0] != sums[1] + sums[2] + sums[3])
        wrong = std::to_string(sums[0]) + " bonds created, " + std::to_string(sums[1]) + " broken, " +
                std::to_string(sums[2]) + " intact, " + std::to_string(sums[3]) + " lost";
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
