#include "bond_nonlinear_cohesion.h"
#include "bonds_fix.h"
#include "core_message.h"
#include "core_bridge.h"
#include "fix_granbond_atoms.h"

#include "domain.h"
#include "fix_property_atom.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

namespace {

void copy3(double *to, const double *from)
{
    to[0] = from[0];
    to[1] = from[1];
    to[2] = from[2];
}

// Position, velocity and angular velocity of local or ghost atom `i`.
void readAtom(const LAMMPS_NS::Atom *atom, int i, double *x, double *v, double *w)
{
    copy3(x, atom->x[i]);
    copy3(v, atom->v[i]);
    copy3(w, atom->omega[i]);
}

// The wall point of a wall contact: `delta` runs from it to the centre `x`.
void wallPoint(const double *x, const double *delta, double *point)
{
    for (int c = 0; c < 3; c++) point[c] = x[c] - delta[c];
}

}

BondNonlinearCohesion::BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                                             ContactModelBase *cmb) :
    CohesionModelBase(lmp, hsetup, cmb),
    parameters_(lmp),
    keepsTangential_(false),
    isWall_(cmb->is_wall()),
    offset_(-1),
    outputOffset_(-1),
    status_(0),
    clumpIds_(0),
    atoms_(0),
    checkedNatoms_(-1),
    firstStep_(-1),
    saidLaw_(false),
    pair_(cmb->is_wall() ? 0 : dynamic_cast<LAMMPS_NS::PairGran *>(hsetup)),
    bonds_(0),
    passing_(false),
    advance_(false),
    mayForm_(false),
    formedThisPass_(false),
    linkedAt_(-1),
    ghostLoads_(0),
    passStep_(-1),
    passAtoms_(-1),
    checkStore_(std::getenv("GRANBOND_CHECK_STORE") != 0),
    warnedLost_(false)
{
    checkCoreLayout(error);
    if (isWall_) {
        // the wall bond's state, then the loads of the latest force pass,
        // so that `compute wall/gran/local ... history` can dump them and
        // the per-contact output pass reports the applied forces
        offset_ = registerStateSlots(hsetup, GB_STATE_KIND_WALL_BOND, error);
        outputOffset_ = registerStateSlots(hsetup, GB_STATE_KIND_BOND_OUTPUT, error);
        // the rest length, whose sign is the status: positive while intact
        status_ = slotNamed(GB_STATE_KIND_WALL_BOND, "rest", error);
        // the names LIGGGHTS-INL publishes, so per-contact tools can find the slots
        cmb->add_history_offset("bondnonlinear_contactflag", offset_);
        cmb->add_history_offset("bondnonlinear_output", outputOffset_);
        // where contact models find whether the wall bond is intact
        // (`model voigt ... contactUnderBond off`)
        cmb->add_history_offset("bondnonlinear_status", offset_ + static_cast<int>(status_));
    } else {
        // pair records hold nothing of the bond: the contact flag's bit
        // says where a bond is (`model voigt ... contactUnderBond off`)
        cmb->add_history_offset(bondedFlagName(), kBondedFlag);
    }
    tally_.wall = isWall_;
    book_ = &BondBook::of(lmp);   // std::map: the address stays
    book_->add(&tally_);
    if (!isWall_) book_->pairBonds = this;
    registerBondStyles(lmp);
}

BondNonlinearCohesion::~BondNonlinearCohesion()
{
    // pair bonds stay in their store with their counts: nothing retires
    if (!isWall_) tally_ = BondTally();
    book_->remove(&tally_);
    if (book_->pairBonds == this) book_->pairBonds = nullptr;
}

bool BondNonlinearCohesion::keepsTangentialFor(int itype, int jtype) const
{
    const GbBondModel *m = parameters_.model(itype, jtype);
    return m && granbond_bond_keeps_contact_tangential(m) != 0;
}

void BondNonlinearCohesion::keepUnderBond(const SurfacesIntersectData &sidata, ForceData &i_forces,
                                          ForceData &j_forces)
{
    GbContactOutput out;
    std::memset(&out, 0, sizeof out);
    for (int k = 0; k < 3; k++) {
        out.force_i[k] = i_forces.delta_F[k];
        out.torque_i[k] = i_forces.delta_torque[k];
        out.torque_j[k] = j_forces.delta_torque[k];
    }
    out.normal_force = sidata.Fn;
    out.touching = 1;
    if (granbond_bond_contact_loads_under_bond(parameters_.model(sidata.itype, sidata.jtype), sidata.delta, sidata.rsq,
                                               &out) != GB_STATUS_OK)
        failed(sidata.i, sidata.j, "the contact under the bond");
    for (int k = 0; k < 3; k++) {
        i_forces.delta_F[k] = out.force_i[k];
        j_forces.delta_F[k] = -out.force_i[k];
        i_forces.delta_torque[k] = out.torque_i[k];
        j_forces.delta_torque[k] = out.torque_j[k];
    }
}

void BondNonlinearCohesion::connectToProperties(PropertyRegistry &registry)
{
    parameters_.connectToProperties(registry);
    keepsTangential_ = keepsLoads_ = false;
    const int n = parameters_.ntypes();
    for (int a = 1; a <= n; a++)
        for (int b = 1; b <= n; b++) {
            if (keepsTangentialFor(a, b)) keepsTangential_ = true;
            const GbBondModel *m = parameters_.model(a, b);
            if (m && granbond_bond_keeps_contact_loads(m)) keepsLoads_ = true;
        }
    // `bonded yes` stores a clump id per atom under this name (LIGGGHTS-INL
    // looks for "bondnonlinear_random_id", which no fix creates)
    clumpIds_ = isWall_ ? 0
                        : static_cast<LAMMPS_NS::FixPropertyAtom *>(modify->find_fix_property(
                              "bond_random_id", "property/atom", "scalar", 0, 0, "cohesion bond/nonlinear", false));
    if (!isWall_) {
        // the bond kind of each pair of types: its model's place in the table
        kinds_.assign(static_cast<size_t>(n + 1) * (n + 1), -1);
        for (int a = 1; a <= n; a++)
            for (int b = 1; b <= n; b++)
                if (parameters_.model(a, b))
                    kinds_[static_cast<size_t>(a) * (n + 1) + b] = std::min(a, b) * (n + 1) + std::max(a, b);
        createsNow_.assign(kinds_.size(), 0);
        bonds_ = bondsFix(lmp);
        linkedAt_ = -1;
        checkRenumbering();
        if (checkStore_ && comm->me == 0) {
            const char *said = "cohesion bond/nonlinear: recounting the bonds after every pass "
                               "(GRANBOND_CHECK_STORE)\n";
            if (screen) fputs(said, screen);
            if (logfile) fputs(said, logfile);
        }
    }
    runChecks(true);
}

// Ends the run if atoms were renumbered since the previous run after bonds
// formed (countRenumbered). Wall bonds live with their particle and are
// not affected. Creates the per-atom record of which atoms were seen
// (fix_granbond_atoms.h, registered with the bond styles), or takes the
// one a restart file brought back.
void BondNonlinearCohesion::checkRenumbering()
{
    atoms_ = static_cast<FixGranbondAtoms *>(fixOrNew(lmp, atomsFixId(), atomsFixStyle()));
    if (!atoms_) endRun(error, FLERR, "cohesion bond/nonlinear: fix granbond/atoms could not be created");
    const long long renumbered = countRenumbered(atom->nlocal, atom->tag, atoms_->seen, world);
    if (renumbered == 0) return;   // the same on every rank
    long long mine = bonds_->counts().created, created = 0;
    MPI_Allreduce(&mine, &created, 1, MPI_LONG_LONG, MPI_SUM, world);
    if (created > 0) endRun(error, FLERR, renumberedMessage("cohesion bond/nonlinear", renumbered));
}

// forgetRecordsOfNewborn (fix_granbond_atoms.h) on the pair list and
// LIGGGHTS's history list (its flags and records): a contact's record
// that names an atom never seen is the deleted atom's.
void BondNonlinearCohesion::forgetRecordsOfNewborn()
{
    const LAMMPS_NS::NeighList *list = pair_->list, *history = pair_->listgranhistory;
    if (!list || !history || !history->firstneigh || !history->firstdouble) return;
    granbond::forgetRecordsOfNewborn(*atoms_, atom->nlocal, atom->nghost, atom->tag, list->inum, list->ilist,
                                     list->numneigh, list->firstneigh, history->firstneigh, history->firstdouble,
                                     pair_->dnum());
}

void BondNonlinearCohesion::beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &)
{
    if (atom->natoms != checkedNatoms_) runChecks(false);
    // at a run's start, and at every step of a box that changes (fix deform)
    if (update->setupflag || domain->box_change) {
        const std::string thin =
            thinPeriodicBox("cohesion bond/nonlinear", domain->dimension, domain->periodicity, domain->prd,
                            neighbor->cutneighmax, neighbor->skin, update->setupflag ? -1 : update->ntimestep);
        if (!thin.empty()) endRun(error, FLERR, thin);
    }
    if (isWall_ || !pair_) return;
    if (atoms_ && (update->setupflag || neighbor->ago == 0)) forgetRecordsOfNewborn();
    // a force pass steps the bonds, a setup pass (a run's start) evaluates
    // them; the per-contact output pass (compute pair/gran/local) changes
    // nothing, and its bonded pairs show no contact loads
    passing_ = sidata.computeflag != 0;
    advance_ = passing_ && sidata.shearupdate;
    mayForm_ = false;
    if (!passing_) return;
    if (update->setupflag || linkedAt_ != neighbor->ncalls) linkBonds();
    GbBondStore *store = bonds_->store();
    // computeDissipatedEnergy on: the engine's surface model made the
    // per-atom table (INL's: the energy, then force and torque sums)
    if (update->setupflag)
        dissipated_ = static_cast<LAMMPS_NS::FixPropertyAtom *>(modify->find_fix_property(
            "dissipated_energy", "property/atom", "vector", 7, 0, "cohesion bond/nonlinear", false));
    // the budget is kept from a run's start while a compute asks for it
    // (the damping loads also for computeDissipatedEnergy), each bond's
    // share while a per-bond output does
    if (update->setupflag &&
        granbond_bond_store_keep_energy_budget(store, energyUsers > 0 || energyOutputUsers > 0 || dissipated_,
                                               energyOutputUsers > 0) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: " + coreReason());
    // a creation step ahead: pairs whose bonds break are kept from it
    bool remember = false, creates = false;
    const GbBondModel *const *table = parameters_.table();
    for (size_t k = 0; k < createsNow_.size(); k++) {
        double reach = 0.0;
        createsNow_[k] = advance_ && table[k] && granbond_bond_creates_at(table[k], update->ntimestep);
        creates = creates || createsNow_[k];
        if (table[k] && granbond_bond_creation_reach(table[k], update->ntimestep + 1, &reach) == GB_STATUS_OK &&
            reach > 0.0)
            remember = true;
    }
    mayForm_ = advance_ && (creates || clumpIds_);
    if (granbond_bond_store_begin_pass(store, update->dt, advance_ ? 1 : 0, remember ? 1 : 0) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: " + coreReason());
    ghostLoads_ = force->newton_pair ? 0 : bonds_->ghostLoads();
    if (bondOutputUsers > 0 && advance_) outputs_.clear();
    stepBonds(advance_);
    takeBroken(advance_);
}

void BondNonlinearCohesion::endPass(SurfacesIntersectData &, ForceData &, ForceData &)
{
    if (isWall_ || !passing_) return;
    finishPairPass();
    passing_ = advance_ = mayForm_ = false;
}

void BondNonlinearCohesion::runChecks(bool runStart)
{
    checkedNatoms_ = atom->natoms;
    if (firstStep_ < 0) firstStep_ = update->ntimestep;
    const int ntypes = parameters_.ntypes();
    const std::vector<GbTypeBodies> bodies =
        gatherTypeBodies(ntypes, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    const std::string styleName = std::string(parameters_.caller()) + (isWall_ ? " (wall)" : "");
    const char *style = styleName.c_str();
    GbCheckReport report;
    if (granbond_bond_timestep_check(parameters_.table(), ntypes, bodies.data(), update->dt, 1, update->unit_style,
                                     style, &report) != GB_STATUS_OK)
        endRun(error, FLERR, std::string(style) + ": " + coreReason());
    if (timestepWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!runStart) return;
    if (!saidLaw_ && comm->me == 0) sayLaw(style);
    saidLaw_ = true;
    const long long dropped = book_->takeDropped(world);
    if (dropped > 0 && comm->me == 0) error->warning(FLERR, droppedMessage(dropped).c_str());
    if (granbond_bond_creation_check(parameters_.table(), ntypes, bodies.data(), firstStep_, 0, isWall_ ? 1 : 0, 1,
                                     update->unit_style, style, &report) != GB_STATUS_OK)
        endRun(error, FLERR, std::string(style) + ": " + coreReason());
    const std::vector<std::string> lines = said_.fresh(report);
    for (size_t k = 0; k < lines.size(); k++)
        if (comm->me == 0) error->warning(FLERR, lines[k].c_str());
}

// The run's opening lines say which law the bonds follow (the core's
// words), each different line once: LIGGGHTS-INL's decks run with the
// write-up's law unless they ask for INL's code.
void BondNonlinearCohesion::sayLaw(const char *style)
{
    std::vector<std::string> said;
    for (int a = 1; a <= parameters_.ntypes(); a++)
        for (int b = a; b <= parameters_.ntypes(); b++) {
            const GbBondModel *m = parameters_.model(a, b);
            char line[512];
            if (!m || granbond_bond_law_line(m, 1, line, sizeof line) != GB_STATUS_OK) continue;
            if (std::find(said.begin(), said.end(), std::string(line)) != said.end()) continue;
            said.push_back(line);
            if (screen) fprintf(screen, "%s: %s\n", style, line);
            if (logfile) fprintf(logfile, "%s: %s\n", style, line);
        }
}

// ------------------------------------------------------------ wall bonds

void BondNonlinearCohesion::account(const GbBondModel *model, int i, const double *wallDelta, const double *state,
                                    bool created, const GbBondOutput &out)
{
    if (created) tally_.created++;
    if (state[status_] > 0.0) tally_.intact++;
    if (out.break_mode == GB_BREAK_MODE_NONE) return;
    tally_.broken++;
    BondBook &book = *book_;
    if (!book.logging()) return;
    // a wall plays sphere j, of radius 0 at the wall point
    double wall[3];
    if (wallDelta) wallPoint(atom->x[i], wallDelta, wall);
    BreakEvent e;
    if (makeBreakEvent(model, out, atom->x[i], wall, atom->radius[i], 0.0, static_cast<double>(atom->tag[i]), 0.0,
                       static_cast<double>(update->ntimestep), e) != GB_STATUS_OK)
        failed(i, 0, "the break log's event");
    book.record(e);
}

void BondNonlinearCohesion::failed(int i, int j, const char *call)
{
    char where[160];
    if (isWall_)
        snprintf(where, sizeof where, "atom %ld and a wall", static_cast<long>(atom->tag[i]));
    else
        snprintf(where, sizeof where, "atoms %ld and %ld", static_cast<long>(atom->tag[i]),
                 static_cast<long>(atom->tag[j]));
    // a core entry's failure is told by the core's reason; the adapter's
    // own, by what it was doing
    const std::string step = " at step " + std::to_string(static_cast<long long>(update->ntimestep));
    const std::string msg = std::strncmp(call, "granbond_", 9) == 0
                                ? "cohesion bond/nonlinear: " + std::string(where) + step + ": " + coreReason()
                                : "cohesion bond/nonlinear: " + std::string(call) + " failed for " + where + step;
    endRunOnThisRank(lmp, FLERR, msg);
}

// A wall bond's step (or creation). Returns true and fills `out` if the
// bond is intact after it: then its loads replace the contact models'.
bool BondNonlinearCohesion::advance(SurfacesCloseData &d, GbBondOutput &out)
{
    const GbBondModel *model = parameters_.model(d.itype, d.jtype);
    if (!model || !d.contact_history) {
        failed(d.i, d.j, model ? "contact history lookup" : "model lookup (types not connected)");
        return false;
    }
    double *const state = d.contact_history + offset_;
    double *const outputSlots = d.contact_history + outputOffset_;
    // Passes that must not advance the state: the setup pass of a run
    // (computeflag, no shearupdate) and the per-contact output pass
    // (compute wall/gran/local). Both report what the last force pass
    // applied, so a run continued (or restarted) starts from the same
    // forces as an uninterrupted one. A law that computes a setup pass's
    // loads afresh (the core says which) does so in the setup pass only.
    if (!d.computeflag || !d.shearupdate) {
        if (!(state[status_] > 0.0)) return false;
        if (!(d.computeflag && setupAfresh(d, model, state, out)) &&
            granbond_bond_output_load(outputSlots, &out) != GB_STATUS_OK)
            failed(d.i, d.j, "granbond_bond_output_load");
        if (d.computeflag) {
            book_->beginPassIfNew(tally_, update);
            tally_.intact++;
        }
        return true;
    }
    book_->beginPassIfNew(tally_, update);
    std::memset(&out, 0, sizeof out);
    bool created = false;
    const bool intact = advanceWall(d, model, state, out, created);
    if (intact && granbond_bond_output_store(&out, outputSlots) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_bond_output_store");
    account(model, d.i, d.delta, state, created, out);
    return intact;
}

bool BondNonlinearCohesion::setupAfresh(SurfacesCloseData &d, const GbBondModel *model, double *state,
                                        GbBondOutput &out)
{
    int32_t recomputed = 0;
    GbSphereKinematics s;
    readAtom(atom, d.i, s.x, s.v, s.w);
    s.radius = d.radi;
    double wallVelocity[3] = {0.0, 0.0, 0.0};
    if (d.v_j) copy3(wallVelocity, d.v_j);
    if (granbond_wall_bond_setup_compute(model, &s, wallVelocity, update->dt, state, &recomputed, &out) !=
        GB_STATUS_OK)
        failed(d.i, d.j, "granbond_wall_bond_setup_compute");
    return recomputed != 0;
}

bool BondNonlinearCohesion::advanceWall(SurfacesCloseData &d, const GbBondModel *model, double *state,
                                        GbBondOutput &out, bool &created)
{
    GbSphereKinematics s;
    readAtom(atom, d.i, s.x, s.v, s.w);
    s.radius = d.radi;
    double wallVelocity[3] = {0.0, 0.0, 0.0};
    if (d.v_j) copy3(wallVelocity, d.v_j);

    // an intact bond cannot be created again: skip the core's creation call
    // (it would return at once, not created)
    if (!(state[status_] > 0.0)) {
        double contactPoint[3];
        wallPoint(s.x, d.delta, contactPoint);
        int32_t made = 0;
        if (granbond_wall_bond_try_create(model, &s, contactPoint, update->ntimestep, state, &made) !=
            GB_STATUS_OK)
            failed(d.i, d.j, "granbond_wall_bond_try_create");
        created = made != 0;
    }
    if (!(state[status_] > 0.0)) return false;
    if (granbond_wall_bond_compute(model, &s, wallVelocity, update->dt, state, &out) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_wall_bond_compute");
    return out.status == GB_BOND_STATUS_INTACT;
}

void BondNonlinearCohesion::apply(const GbBondOutput &out, ForceData &i_forces, ForceData &)
{
    for (int c = 0; c < 3; c++) {
        i_forces.delta_F[c] += out.force_i[c];
        i_forces.delta_torque[c] += out.torque_i[c];
    }
}

void BondNonlinearCohesion::intersecting(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    GbBondOutput out;
    if (!advance(sidata, out)) return;   // the contact model acts alone
    // an intact bond replaces what normal, tangential and rolling models
    // added, or adds to it (keepsContactLoads)
    if (!keepsContactLoads(sidata.itype, sidata.jtype)) {
        i_forces.reset();
        j_forces.reset();
    }
    apply(out, i_forces, j_forces);
}

void BondNonlinearCohesion::close(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
{
    GbBondOutput out;
    if (!advance(scdata, out)) return;
    apply(out, i_forces, j_forces);
    scdata.has_force_update = true;   // otherwise the engine drops the forces
}

}
}
