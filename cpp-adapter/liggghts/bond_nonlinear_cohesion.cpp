#include "bond_nonlinear_cohesion.h"
#include "core_message.h"
#include "core_bridge.h"
#include "vector_adds.h"
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

void setContactFlag(SurfacesCloseData &d, bool keep)
{
    if (!d.contact_flags) return;   // walls have none
    if (keep)
        *d.contact_flags |= CONTACT_COHESION_MODEL;   // keeps the history at re-neighbouring
    else
        *d.contact_flags &= ~CONTACT_COHESION_MODEL;
}

}

BondNonlinearCohesion::BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                                             ContactModelBase *cmb) :
    CohesionModelBase(lmp, hsetup, cmb),
    parameters_(lmp),
    keepsTangential_(false),
    isWall_(cmb->is_wall()),
    stateLen_(granbond_state_len(cmb->is_wall() ? GB_STATE_KIND_WALL_BOND : GB_STATE_KIND_BOND)),
    offset_(-1),
    outputOffset_(-1),
    status_(0),
    statusAt_(0),
    clumpIds_(0),
    atoms_(0),
    checkedNatoms_(-1),
    firstStep_(-1),
    saidLaw_(false),
    lossCheck_(false),
    warnedLost_(false),
    pair_(cmb->is_wall() ? 0 : dynamic_cast<LAMMPS_NS::PairGran *>(hsetup)),
    sweeping_(false),
    direct_(false),
    createsNow_(false),
    cursor_(0),
    lastAtom_(-1),
    aheadTo_(-1),
    indexedAt_(-1),
    rows_(false),
    pruneIndex_(false),
    checkIndex_(std::getenv("GRANBOND_CHECK_INDEX") != 0)
{
    checkCoreLayout(error);
    // after the core's state, the loads of the latest force pass, so that
    // `compute pair/gran/local ... history` (and `wall/gran/local`) can dump
    // them and the per-contact output pass reports the applied forces: for
    // pairs the core's bond record, for walls the wall bond's state and the
    // same loads
    if (isWall_) {
        offset_ = registerStateSlots(hsetup, GB_STATE_KIND_WALL_BOND, error);
        outputOffset_ = registerStateSlots(hsetup, GB_STATE_KIND_BOND_OUTPUT, error);
        status_ = slotNamed(GB_STATE_KIND_WALL_BOND, "status", error);
    } else {
        GbRecordLayout layout;
        granbond_record_layout(0, &layout);
        offset_ = registerStateSlots(hsetup, GB_STATE_KIND_BOND_RECORD, error);
        outputOffset_ = offset_ + static_cast<int>(layout.loads);
        status_ = layout.status;
    }
    statusAt_ = static_cast<size_t>(offset_) + status_;
    // the name LIGGGHTS-INL publishes, so per-contact tools can find the slots
    cmb->add_history_offset("bondnonlinear_contactflag", offset_);
    cmb->add_history_offset("bondnonlinear_output", outputOffset_);
    // where contact models find whether the pair's bond is intact
    // (`model voigt ... contactUnderBond off`)
    cmb->add_history_offset("bondnonlinear_status", offset_ + status_);
    tally_.wall = isWall_;
    book_ = &BondBook::of(lmp);   // std::map: the address stays
    book_->add(&tally_);
    if (!isWall_) book_->pairBonds = this;
    registerBondStyles(lmp);
}

BondNonlinearCohesion::~BondNonlinearCohesion()
{
    book_->remove(&tally_);
    if (book_->pairBonds == this) book_->pairBonds = nullptr;
}

bool BondNonlinearCohesion::keepsTangentialFor(int itype, int jtype) const
{
    const GbBondModel *m = parameters_.model(itype, jtype);
    return m && granbond_bond_keeps_contact_tangential(m) != 0;
}

void BondNonlinearCohesion::connectToProperties(PropertyRegistry &registry)
{
    parameters_.connectToProperties(registry);
    keepsTangential_ = false;
    for (int a = 1; a <= parameters_.ntypes(); a++)
        for (int b = 1; b <= parameters_.ntypes(); b++)
            if (keepsTangentialFor(a, b)) keepsTangential_ = true;
    // `bonded yes` stores a clump id per atom under this name (LIGGGHTS-INL
    // looks for "bondnonlinear_random_id", which no fix creates)
    clumpIds_ = isWall_ ? 0
                        : static_cast<LAMMPS_NS::FixPropertyAtom *>(modify->find_fix_property(
                              "bond_random_id", "property/atom", "scalar", 0, 0, "cohesion bond/nonlinear", false));
    if (!isWall_) checkRenumbering();
    if (!isWall_ && checkIndex_ && comm->me == 0) {
        const char *said = "cohesion bond/nonlinear: checking the index of bonds after every pass "
                           "(GRANBOND_CHECK_INDEX)\n";
        if (screen) fputs(said, screen);
        if (logfile) fputs(said, logfile);
    }
    runChecks(true);
    lossCheck_ = !isWall_;
}

// Ends the run if atoms were renumbered since the previous run after bonds
// formed (countRenumbered). Wall bonds live with their particle and are
// not affected. Creates the per-atom record of which atoms were seen
// (fix_granbond_atoms.h, registered with the bond styles), or takes the
// one a restart file brought back.
void BondNonlinearCohesion::checkRenumbering()
{
    int ifix = modify->find_fix(atomsFixId());
    if (ifix < 0) {
        char id[32], group[] = "all", style[32];
        std::snprintf(id, sizeof id, "%s", atomsFixId());
        std::snprintf(style, sizeof style, "%s", atomsFixStyle());
        char *args[] = {id, group, style};
        modify->add_fix(3, args);
        ifix = modify->find_fix(atomsFixId());
    }
    if (ifix < 0) endRun(error, FLERR, "cohesion bond/nonlinear: fix granbond/atoms could not be created");
    atoms_ = static_cast<FixGranbondAtoms *>(modify->fix[ifix]);
    const long long renumbered = countRenumbered(atom->nlocal, atom->tag, atoms_->seen, world);
    if (renumbered == 0) return;   // the same on every rank
    long long mine = tally_.created, created = 0;
    MPI_Allreduce(&mine, &created, 1, MPI_LONG_LONG, MPI_SUM, world);
    if (created > 0) endRun(error, FLERR, renumberedMessage("cohesion bond/nonlinear", renumbered));
}

// forgetRecordsOfNewborn (fix_granbond_atoms.h) on the pair list and
// LIGGGHTS's history list (its flags and records).
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
    if (atom->natoms != checkedNatoms_) {
        runChecks(false);
        lossCheck_ = !isWall_;
    }
    // at a run's start, and at every step of a box that changes (fix deform)
    if (update->setupflag || domain->box_change) {
        const std::string thin =
            thinPeriodicBox("cohesion bond/nonlinear", domain->dimension, domain->periodicity, domain->prd,
                            neighbor->cutneighmax, neighbor->skin, update->setupflag ? -1 : update->ntimestep);
        if (!thin.empty()) endRun(error, FLERR, thin);
    }
    if (atoms_ && (update->setupflag || neighbor->ago == 0)) forgetRecordsOfNewborn();
    // Every force pass sweeps the pair bonds before the engine's loop. Their
    // loads go straight to the atoms, unless something in the engine reads
    // each pair's forces as the loop applies them (stored contact forces,
    // summed normal forces or deltas): then each pair's callback applies its
    // bond's loads. (compute pair/gran/local reads them in a pass of its
    // own, which advances nothing: the callbacks apply the kept loads.)
    sweeping_ = pair_ && sidata.computeflag && sidata.shearupdate;
    direct_ = sweeping_ && !pair_->storeContactForces() && !pair_->storeContactForcesStress() &&
              !pair_->store_sum_normal_force() && !pair_->storeSumDelta();
    brokeNow_.clear();
    if (sweeping_) {
        book_->beginPassIfNew(tally_, update);
        sweepIndex();
    }
    // the per-contact output pass (compute pair/gran/local) applies the
    // loads the records keep
    if (!sidata.computeflag) writeBack();
    cursor_ = 0;
    lastAtom_ = -1;
    // whether any bond may form in this pass (the core says, per bond type)
    createsNow_ = false;
    const int n = parameters_.ntypes();
    for (int t = 0; sweeping_ && t < (n + 1) * (n + 1); t++) {
        const GbBondModel *model = parameters_.table()[t];
        if (model && granbond_bond_creates_at(model, update->ntimestep)) createsNow_ = true;
    }
}

void BondNonlinearCohesion::endPass(SurfacesIntersectData &, ForceData &, ForceData &)
{
    if (sweeping_) {
        sweepAhead(pair_->list->inum - 1);   // atoms the loop made no callback for
        GbSweepTally t = {};
        for (size_t x = 0; x < sweptTo_.size(); x++) sweepRange(index_[x], sweptTo_[x], sweepEnd_[x], t);
        tally_.intact += t.intact;
        if (pruneIndex_)
            for (BondIndex &b : index_) b.keepIntact();
        pruneIndex_ = false;
        if (checkIndex_) checkIndex();
        sweeping_ = direct_ = false;
    }
    if (lossCheck_) countVanished();
}

// After the atom count changed, or a run started (atoms deleted between
// runs), the counts of the pass just completed are balanced against those
// of the previous check (BondBalance).
void BondNonlinearCohesion::countVanished()
{
    lossCheck_ = false;
    book_->beginPassIfNew(tally_, update);   // a rank without bonds in this pass: 0 intact
    const double mine[3] = {static_cast<double>(tally_.created), static_cast<double>(tally_.broken),
                            static_cast<double>(tally_.intact)};
    double all[3];
    MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, world);
    const long long vanished = balance_.vanished(all[0], all[1], all[2]);
    if (vanished == 0 || comm->me != 0) return;
    tally_.lost += vanished;
    if (warnedLost_) return;
    warnedLost_ = true;
    error->warning(FLERR, vanishedMessage("cohesion bond/nonlinear", vanished, update->ntimestep,
                                          "they are counted as lost in compute bond/counter (columns 7 and 8), "
                                          "later ones without a warning")
                              .c_str());
}

inline void BondNonlinearCohesion::pairKinematics(const SurfacesCloseData &d, GbPairKinematics &k) const
{
    // atom->omega, not d.omega_i/j: in surfacesClose those are left over
    // from the previous overlapping pair
    readAtom(atom, d.i, k.x_i, k.v_i, k.w_i);
    readAtom(atom, d.j, k.x_j, k.v_j, k.w_j);
    k.radius_i = d.radi;
    k.radius_j = d.radj;
}

// What the engine's pair loop does with a pair's loads (relaxation factor,
// newton off, virial), for a bond the sweep advanced: j takes -force_i. The
// atoms' arrays are blocks of 3 doubles per atom, indexed from `sums`, read
// once per sweep: a core call between two bonds would make the compiler
// read every row pointer again.
inline void BondNonlinearCohesion::addToAtoms(const AtomSums &sums, int i, int j, const GbBondOutput &out)
{
    const size_t I = 3 * static_cast<size_t>(i), J = 3 * static_cast<size_t>(j);
    const double relaxI = pair_->relax(i);
    addScaled3(sums.f + I, relaxI, out.force_i);
    addScaled3(sums.torque + I, relaxI, out.torque_i);
    if (sums.newton || j < sums.nlocal) {
        const double relaxJ = pair_->relax(j);
        subtractScaled3(sums.f + J, relaxJ, out.force_i);
        addScaled3(sums.torque + J, relaxJ, out.torque_j);
    }
    if (sums.virial) {
        const double *xi = atom->x[i], *xj = atom->x[j];
        pair_->ev_tally_xyz(i, j, sums.nlocal, sums.newton, 0.0, 0.0, out.force_i[0], out.force_i[1],
                            out.force_i[2], xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
    }
}

// The index, built from the records of the lists: every pair whose record
// holds an intact bond (bond_index.h). Rebuilt at the first swept pass after
// the engine builds its lists, or after a pass of the per-pair path.
void BondNonlinearCohesion::indexBonds()
{
    indexedAt_ = neighbor->ncalls;
    rows_ = direct_;
    for (size_t x = 0; x < index_.size(); x++) index_[x].clear();
    const LAMMPS_NS::NeighList *list = pair_->list, *history = pair_->listgranhistory;
    if (!list || !history || !history->firstneigh || !history->firstdouble) return;
    const int dnum = pair_->dnum();
    for (int ii = 0; ii < list->inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        int *flags = history->firstneigh[i];
        double *records = history->firstdouble[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            double *record = records + static_cast<size_t>(dnum) * jj + offset_;
            if (record[status_] != GB_BOND_STATUS_INTACT) continue;
            const int j = jlist[jj] & NEIGHMASK;
            const GbBondModel *model = parameters_.model(atom->type[i], atom->type[j]);
            if (!model) continue;   // the per-pair path reports it
            indexFor(model).add(i, j, countsHere(i, j), record, &flags[jj]);
        }
    }
    for (BondIndex &b : index_) b.ordered = b.size();
}

// The swept pass's bonds, advanced ahead of the engine's pair loop: the
// bonds of the first atoms of the list now, the rest block by block as the
// loop reaches their atoms (sweepAhead), so that the loop, whose contact
// models and callbacks read each bonded record again, finds them in cache.
// Their loads go straight to the atoms (unless the pairs' callbacks apply
// them).
void BondNonlinearCohesion::sweepIndex()
{
    // rows only where the callbacks need not read the loads from the
    // records (indexFor): a pass that does indexes the homes again
    if (indexedAt_ == neighbor->ncalls && rows_ != direct_) writeBack();
    if (indexedAt_ != neighbor->ncalls || rows_ != direct_) indexBonds();
    for (BondIndex &b : index_) keepLoadsIfRead(b);
    sweptTo_.assign(index_.size(), 0);
    sweepEnd_.resize(index_.size());
    for (size_t x = 0; x < index_.size(); x++) sweepEnd_[x] = index_[x].ordered;
    aheadTo_ = -1;
    // bonds formed since the lists were built lie out of their order: now
    GbSweepTally t = {};
    for (size_t x = 0; x < index_.size(); x++) sweepRange(index_[x], sweepEnd_[x], index_[x].size(), t);
    sweepAhead(kSweepAheadAtoms);
    tally_.intact += t.intact;
}

void BondNonlinearCohesion::sweepRange(BondIndex &b, size_t first, size_t last, GbSweepTally &t)
{
    if (first == last) return;
    const size_t breaks = b.broken.size();
    size_t bad = 0;
    const AtomSums sums = {atom->f[0], atom->torque[0], atom->nlocal, force->newton_pair, pair_->evflag != 0};
    const GbStatus status =
        direct_ ? b.sweep(atom, first, last, true, update->dt, t, bad,
                          [&](size_t k, const GbBondOutput &out) {
                              addToAtoms(sums, b.pairs[2 * k], b.pairs[2 * k + 1], out);
                          })
                : b.sweep(atom, first, last, true, update->dt, t, bad, [](size_t, const GbBondOutput &) {});
    if (status != GB_STATUS_OK) failed(b.pairs[2 * bad], b.pairs[2 * bad + 1], "granbond_bond_sweep");
    settleBroken(b, breaks);
    pruneIndex_ = pruneIndex_ || b.broken.size() > breaks;
}

// Sweeps the bonds of the list's atoms up to position `upto` (the index
// holds them in list order).
void BondNonlinearCohesion::sweepAhead(int upto)
{
    const LAMMPS_NS::NeighList *list = pair_->list;
    if (!list) return;
    const int last = upto < list->inum - 1 ? upto : list->inum - 1;
    GbSweepTally t = {};
    for (size_t x = 0; x < sweptTo_.size(); x++) {   // indices made in the loop hold only bonds formed in it
        BondIndex &b = index_[x];
        size_t end = sweptTo_[x];
        for (int q = aheadTo_ + 1; q <= last; q++)
            while (end < sweepEnd_[x] && b.pairs[2 * end] == list->ilist[q]) end++;
        sweepRange(b, sweptTo_[x], end, t);
        sweptTo_[x] = end;
    }
    tally_.intact += t.intact;
    aheadTo_ = last;
}

// The bonds of `b` that broke in a sweep, from its `from`-th break on:
// counted and logged; their pairs' callbacks then see a broken bond (the
// contact models act alone), and no bond forms on them in this pass.
void BondNonlinearCohesion::settleBroken(BondIndex &b, size_t from)
{
    for (size_t m = from; m < b.broken.size(); m++) {
        const size_t k = b.broken[m];
        account(b.model, b.pairs[2 * k], b.pairs[2 * k + 1], 0, b.records[k], false, b.brokenOut[m]);
        *b.flags[k] &= ~CONTACT_COHESION_MODEL;
        brokeNow_.insert(b.homes[k]);
    }
}

// The index of `model`'s bonds, its records without the contact's state
// (LIGGGHTS's own models keep it), set for this pass. Their states are
// stepped in rows (bond_index.h) where the pass's loads go straight to the
// atoms: a row has no room for them.
BondIndex &BondNonlinearCohesion::indexFor(const GbBondModel *model)
{
    BondIndex &b = indexOf(index_, model);
    b.pass.with_contact = 0;
    if (b.size() == 0) {
        GbRecordLayout layout;
        granbond_record_layout(0, &layout);
        if (rows_)
            b.useRows(layout);
        else
            b.useHomes();
    }
    keepLoadsIfRead(b);
    return b;
}

// A pass whose pairs' callbacks read the loads from the records (not direct)
// has the sweep keep them there.
void BondNonlinearCohesion::keepLoadsIfRead(BondIndex &b) const { b.pass.keep_loads = direct_ ? 0 : 1; }

// Only while the index holds the records of the lists as they stand: an
// older index's bonds were written back before the engine moved the
// records (fix granbond/atoms' pre_exchange).
bool BondNonlinearCohesion::writeBack()
{
    if (indexedAt_ != neighbor->ncalls) return false;
    bool rows = false;
    for (BondIndex &b : index_) {
        rows = rows || (b.usesRows() && b.size() > 0);
        if (b.writeBack() != GB_STATUS_OK)
            endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: filing the bonds' loads: " + coreReason());
    }
    return rows;
}

// GRANBOND_CHECK_INDEX: the index recounted from the records after a swept
// pass (bond_index.h, checkIndex); a mismatch ends the run.
void BondNonlinearCohesion::checkIndex()
{
    const LAMMPS_NS::NeighList *list = pair_->list, *history = pair_->listgranhistory;
    if (!list || !history || !history->firstneigh || !history->firstdouble) return;
    const int dnum = pair_->dnum();
    const std::string wrong = granbond::checkIndex(index_, status_, false, [&](auto seen) {
        for (int ii = 0; ii < list->inum; ii++) {
            const int i = list->ilist[ii];
            for (int jj = 0; jj < list->numneigh[i]; jj++) {
                const int j = list->firstneigh[i][jj] & NEIGHMASK;
                if (!parameters_.model(atom->type[i], atom->type[j])) continue;
                seen(history->firstdouble[i] + static_cast<size_t>(dnum) * jj + offset_,
                     &history->firstneigh[i][jj]);
            }
        }
    });
    if (!wrong.empty())
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: index check at step " +
                                         std::to_string(static_cast<long long>(update->ntimestep)) + ": " + wrong);
}

void BondNonlinearCohesion::runChecks(bool runStart)
{
    checkedNatoms_ = atom->natoms;
    if (firstStep_ < 0) firstStep_ = update->ntimestep;
    const int ntypes = parameters_.ntypes();
    const std::vector<GbTypeBodies> bodies =
        gatherTypeBodies(ntypes, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    const char *style = isWall_ ? "cohesion bond/nonlinear (wall)" : "cohesion bond/nonlinear";
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

bool BondNonlinearCohesion::countsHere(int i, int j) const
{
    // walls: only the particle's owner computes the contact; pairs: once
    // per pair, even where the pair straddles two ranks
    return isWall_ || pairCountsHere(i, j, atom->nlocal, atom->tag);
}

void BondNonlinearCohesion::account(const GbBondModel *model, int i, int j, const double *wallDelta,
                                    const double *state, bool created, const GbBondOutput &out)
{
    if (!countsHere(i, j)) return;
    if (created) tally_.created++;
    if (state[status_] == GB_BOND_STATUS_INTACT) tally_.intact++;
    if (out.break_mode == GB_BREAK_MODE_NONE) return;
    tally_.broken++;
    BondBook &book = *book_;
    if (!book.logging()) return;
    // a wall plays sphere j, of radius 0 at the wall point
    double wall[3];
    if (isWall_ && wallDelta) wallPoint(atom->x[i], wallDelta, wall);
    BreakEvent e;
    if (makeBreakEvent(model, out, atom->x[i],
                       isWall_ ? wall : atom->x[j], atom->radius[i], isWall_ ? 0.0 : atom->radius[j],
                       static_cast<double>(atom->tag[i]), isWall_ ? 0.0 : static_cast<double>(atom->tag[j]),
                       static_cast<double>(update->ntimestep), e) != GB_STATUS_OK)
        failed(i, j, "the break log's event");
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

bool BondNonlinearCohesion::advance(SurfacesCloseData &d, GbBondOutput &out)
{
    const GbBondModel *model = parameters_.model(d.itype, d.jtype);
    if (!model || !d.contact_history) {
        failed(d.i, d.j, model ? "contact history lookup" : "model lookup (types not connected)");
        return false;
    }
    double *const history = d.contact_history + offset_;
    double *const outputSlots = d.contact_history + outputOffset_;
    // Passes that must not advance the state: the setup pass of a run
    // (computeflag, no shearupdate) and the per-contact output pass
    // (compute pair/gran/local, wall/gran/local). Both report what the last
    // force pass applied, so a run continued (or restarted) starts from the
    // same forces as an uninterrupted one.
    // A law that computes a setup pass's loads afresh (the core says which)
    // does so in the setup pass only.
    if (!d.computeflag || !d.shearupdate) {
        if (history[status_] != GB_BOND_STATUS_INTACT) return false;
        if (!(d.computeflag && setupAfresh(d, model, history, out)) &&
            granbond_bond_output_load(outputSlots, &out) != GB_STATUS_OK)
            failed(d.i, d.j, "granbond_bond_output_load");
        if (d.computeflag) {
            book_->beginPassIfNew(tally_, update);
            if (countsHere(d.i, d.j)) tally_.intact++;
        }
        return true;
    }
    book_->beginPassIfNew(tally_, update);
    double *const state = history;
    std::memset(&out, 0, sizeof out);
    bool created = false;
    if (!isWall_) {
        if (!sweeping_) {
            failed(d.i, d.j, "a force pass without the engine's beginPass");
            return false;
        }
        // created now (the rules read this pair's data), then indexed; a
        // pair the rules cannot bond in this step (the core says, from the
        // status and the step) needs no kinematics, unless it may be a
        // `bonded yes` clump's
        if (!clumpIds_ && !granbond_bond_may_create(model, state, update->ntimestep)) return false;
        // a bond that broke in this pass's sweep forms again at the
        // earliest in the next pass, as when it is stepped in its pair's turn
        if (!brokeNow_.empty() && brokeNow_.count(state)) return false;
        GbPairKinematics k;
        pairKinematics(d, k);
        createPair(d, model, k, state, created);
        if (state[status_] != GB_BOND_STATUS_INTACT) return false;
        if (created && countsHere(d.i, d.j)) tally_.created++;
        return sweepNow(form(d, model), out);
    }
    const bool intact = advanceWall(d, model, state, out, created);
    if (intact && granbond_bond_output_store(&out, outputSlots) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_bond_output_store");
    account(model, d.i, d.j, d.delta, state, created, out);
    return intact;
}

// A bond that formed in the pass's loop: advanced at once, and its loads
// applied by its pair's callback, in the loop's order; the index drops it
// at the pass's end if it broke at once (then the contact models' loads
// stand).
bool BondNonlinearCohesion::sweepNow(const Formed &f, GbBondOutput &out)
{
    BondIndex &b = index_[f.index];
    GbSweepTally t = {};
    size_t bad = 0;
    const size_t breaks = b.broken.size();
    if (b.sweep(atom, f.at, b.size(), true, update->dt, t, bad, [&](size_t, const GbBondOutput &held) { out = held; }) !=
        GB_STATUS_OK)
        failed(b.pairs[2 * bad], b.pairs[2 * bad + 1], "granbond_bond_sweep");
    tally_.intact += t.intact;
    if (b.broken.size() == breaks) return true;
    out = b.brokenOut.back();
    settleBroken(b, breaks);
    pruneIndex_ = true;
    return false;
}

void BondNonlinearCohesion::createPair(const SurfacesCloseData &d, const GbBondModel *model,
                                       const GbPairKinematics &k, double *state, bool &created)
{
    int32_t made = 0;
    if (granbond_bond_try_create(model, &k, update->ntimestep, state, &made) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_bond_try_create");
    // spheres of one `bonded yes` clump, in the first force pass after
    // their insertion (the id is the insertion step plus a fraction)
    if (!made && clumpIds_ && state[status_] == GB_BOND_STATUS_UNBONDED) {
        const double *ids = clumpIds_->vector_atom;
        if (ids[d.i] >= 0.0 && ids[d.i] == ids[d.j] && static_cast<double>(update->ntimestep) < ids[d.i] &&
            granbond_bond_create_now(model, &k, state, &made) != GB_STATUS_OK)
            failed(d.i, d.j, "granbond_bond_create_now");
    }
    created = made != 0;
}

bool BondNonlinearCohesion::setupAfresh(SurfacesCloseData &d, const GbBondModel *model, double *state,
                                        GbBondOutput &out)
{
    int32_t recomputed = 0;
    if (isWall_) {
        GbSphereKinematics s;
        readAtom(atom, d.i, s.x, s.v, s.w);
        s.radius = d.radi;
        double wallVelocity[3] = {0.0, 0.0, 0.0};
        if (d.v_j) copy3(wallVelocity, d.v_j);
        if (granbond_wall_bond_setup_compute(model, &s, wallVelocity, update->dt, state, &recomputed, &out) !=
            GB_STATUS_OK)
            failed(d.i, d.j, "granbond_wall_bond_setup_compute");
    } else {
        GbPairKinematics k;
        pairKinematics(d, k);
        if (granbond_bond_setup_compute(model, &k, update->dt, state, &recomputed, &out) != GB_STATUS_OK)
            failed(d.i, d.j, "granbond_bond_setup_compute");
    }
    // The trial step moved the record's history extremes: the next swept
    // pass indexes the records again rather than stepping rows copied
    // before it.
    if (recomputed) indexedAt_ = -1;
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
    if (state[status_] != GB_BOND_STATUS_INTACT) {
        double contactPoint[3];
        wallPoint(s.x, d.delta, contactPoint);
        int32_t made = 0;
        if (granbond_wall_bond_try_create(model, &s, contactPoint, update->ntimestep, state, &made) !=
            GB_STATUS_OK)
            failed(d.i, d.j, "granbond_wall_bond_try_create");
        created = made != 0;
    }
    if (state[status_] != GB_BOND_STATUS_INTACT) return false;
    if (granbond_wall_bond_compute(model, &s, wallVelocity, update->dt, state, &out) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_wall_bond_compute");
    return out.status == GB_BOND_STATUS_INTACT;
}

void BondNonlinearCohesion::apply(const GbBondOutput &out, ForceData &i_forces, ForceData &j_forces)
{
    for (int c = 0; c < 3; c++) {
        i_forces.delta_F[c] += out.force_i[c];
        i_forces.delta_torque[c] += out.torque_i[c];
    }
    if (isWall_) return;
    for (int c = 0; c < 3; c++) {
        j_forces.delta_F[c] -= out.force_i[c];
        j_forces.delta_torque[c] += out.torque_j[c];
    }
}

// The loads the sweep kept in the pair's record for a bond it advanced, for
// the callback to apply.
void BondNonlinearCohesion::applyKept(SurfacesCloseData &d, ForceData &i_forces, ForceData &j_forces)
{
    GbBondOutput out;
    if (granbond_bond_output_load(d.contact_history + outputOffset_, &out) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_bond_output_load");
    apply(out, i_forces, j_forces);
}

// The loop's first callback of atom i in a swept pass: the sweep is kept
// at least half its look-ahead in front of the loop (sweepAhead), so the
// records the engine's contact models read first are still in cache from
// the sweep. Requesting the next atom's records too (docs/performance.md)
// cost instructions and gained no time; the pair loop walks the neighbour
// list in order.
void BondNonlinearCohesion::atomReached(int i)
{
    lastAtom_ = i;
    const LAMMPS_NS::NeighList *list = pair_->list;
    if (!list) return;
    while (cursor_ < list->inum && list->ilist[cursor_] != i) cursor_++;
    if (cursor_ + kSweepAheadAtoms / 2 > aheadTo_ && aheadTo_ < list->inum - 1)
        sweepAhead(cursor_ + kSweepAheadAtoms);
}

// A pair whose bond the pass swept (an intact bond: the sweep advanced it
// before the loop): the bond replaces the contact models' loads, and the
// pair's flag keeps its record.
inline bool BondNonlinearCohesion::swept(SurfacesCloseData &d)
{
    if (sweeping_ && d.i != lastAtom_) atomReached(d.i);
    if (!sweeping_ || !d.contact_history || d.contact_history[statusAt_] != GB_BOND_STATUS_INTACT) return false;
    setContactFlag(d, true);
    return true;
}

// A bond that formed in the loop of a force pass, added to the index.
BondNonlinearCohesion::Formed BondNonlinearCohesion::form(SurfacesCloseData &d, const GbBondModel *model)
{
    BondIndex &b = indexFor(model);
    b.add(d.i, d.j, countsHere(d.i, d.j), d.contact_history + offset_, d.contact_flags);
    Formed f;
    f.index = static_cast<size_t>(&b - &index_[0]);
    f.at = b.size() - 1;
    return f;
}

// A pair without an intact bond in a swept pass in which no bond can
// form: the contact model acts alone, as the general path would decide
// after the core's creation rules.
inline bool BondNonlinearCohesion::unbondable(SurfacesCloseData &d)
{
    if (!sweeping_ || createsNow_ || clumpIds_ || !d.contact_history ||
        d.contact_history[statusAt_] == GB_BOND_STATUS_INTACT)
        return false;
    if (!parameters_.model(d.itype, d.jtype)) return false;   // the general path reports it
    setContactFlag(d, false);
    return true;
}

void BondNonlinearCohesion::intersecting(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    // the contact models have no normal to work with (the engine's would
    // give nan), nor has the bond: stop, as the core does in LAMMPS
    if (!isWall_ && sidata.rsq == 0.0)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: atoms " + std::to_string(static_cast<long>(atom->tag[sidata.i])) +
                                         " and " + std::to_string(static_cast<long>(atom->tag[sidata.j])) + " at step " +
                                         std::to_string(static_cast<long long>(update->ntimestep)) +
                                         ": coincident centres: the pair has no axis; place the atoms apart");
    if (swept(sidata)) {
        i_forces.reset();
        j_forces.reset();
        if (!direct_) applyKept(sidata, i_forces, j_forces);
        return;
    }
    if (unbondable(sidata)) return;
    GbBondOutput out;
    const bool intact = advance(sidata, out);
    setContactFlag(sidata, intact);
    if (!intact) return;   // the contact model acts alone
    // an intact bond replaces what normal, tangential and rolling models added
    i_forces.reset();
    j_forces.reset();
    apply(out, i_forces, j_forces);
}

void BondNonlinearCohesion::close(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
{
    if (swept(scdata)) {
        if (direct_) return;
        applyKept(scdata, i_forces, j_forces);
        scdata.has_force_update = true;   // otherwise the engine drops the forces
        return;
    }
    if (unbondable(scdata)) return;
    GbBondOutput out;
    const bool intact = advance(scdata, out);
    setContactFlag(scdata, intact);
    if (!intact) return;
    apply(out, i_forces, j_forces);
    scdata.has_force_update = true;   // otherwise the engine drops the forces
}

}
}
