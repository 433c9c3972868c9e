#include "bond_book.h"
#include "atoms_fix.h"
#include "bonds_fix.h"
#include "wall_bonds_fix.h"
#include "bond_local.h"
#include "bond_energy.h"
#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"
#include "fix_granbond_atoms.h"
#include "combination_check.h"
#include "deck_words.h"
#include "engine_member.h"

#include "compute.h"
#include "fix.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

namespace granbond {
namespace liggghts {

BondBook &BondBook::of(LAMMPS_NS::LAMMPS *lmp)
{
    static std::map<LAMMPS_NS::LAMMPS *, BondBook> books;
    BondBook &book = books[lmp];
    book.lmp_ = lmp;
    return book;
}

void BondBook::add(BondTally *t)
{
    // the first model of a new simulation (after `clear`): the removed
    // models belonged to the previous one
    if (tallies_.empty() && lmp_ && lmp_->update && lmp_->update->ntimestep == 0) {
        retiredPair_ = retiredWall_ = BondTally();
        dropped_ = 0;
    }
    tallies_.push_back(t);
}

void BondBook::remove(BondTally *t)
{
    const size_t before = tallies_.size();
    tallies_.erase(std::remove(tallies_.begin(), tallies_.end(), t), tallies_.end());
    if (tallies_.size() == before) return;
    BondTally &r = t->wall ? retiredWall_ : retiredPair_;
    r.created += t->created;
    r.broken += t->broken;
    r.lost += t->lost + t->intact;
    dropped_ += t->intact;
}

long long BondBook::takeDropped(MPI_Comm world)
{
    long long all = 0;
    MPI_Allreduce(&dropped_, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    dropped_ = 0;
    return all;
}

std::string droppedMessage(long long dropped)
{
    const int64_t counts[4] = {dropped, 0, 0, 0};
    GbCheckReport report;
    if (granbond_ledger_notice(GRANBOND_NOTICE_DROPPED_LIGGGHTS, counts, 0, nullptr, &report) != GB_STATUS_OK)
        return "cohesion bond/nonlinear: " + coreReason();
    return report.message;
}

void BondTally::take(const GbStoreCounts &c)
{
    double row[GRANBOND_COUNTS_ROW_LEN];
    granbond_store_counts_row(&c, row);
    created = c.created;
    broken = static_cast<long long>(row[1]);
    lost = static_cast<long long>(row[7]);
    intact = c.intact;
}

void BondBook::refresh(bool collective)
{
    for (BondTally *t : tallies_)
        if (t->refresh) t->refresh(t->owner, collective);
}

void BondBook::localTotals(double out[kTotals], bigint step, bool restored) const
{
    for (int k = 0; k < kTotals; k++) out[k] = 0.0;
    for (int wall = 0; wall < 2; wall++) {
        const BondTally &t = wall ? retiredWall_ : retiredPair_;
        out[3 * wall] += static_cast<double>(t.created);
        out[3 * wall + 1] += static_cast<double>(t.broken);
        out[6 + wall] += static_cast<double>(t.lost);
    }
    for (const BondTally *t : tallies_) {
        double *o = out + (t->wall ? 3 : 0);
        o[0] += static_cast<double>(t->created);
        o[1] += static_cast<double>(t->broken);
        if (t->passStep == step) o[2] += static_cast<double>(t->intact);
        out[t->wall ? 7 : 6] += static_cast<double>(t->lost);
    }
    if (restored)
        for (int k = 0; k < kTotals; k++) out[k] += restored_[k];
}

void BondBook::restoreTotals(const double totals[kTotals], bool root)
{
    // intact bonds are counted afresh; the pair bonds' events come back
    // with their store (fix granbond/bonds)
    for (int k = 0; k < kTotals; k++) restored_[k] = root && k != 0 && k != 1 && k != 2 && k != 5 && k != 6 ? totals[k] : 0.0;
}

BondNonlinearCohesion *PairBondsUse::need(LAMMPS_NS::LAMMPS *lmp, const char *style) const
{
    BondNonlinearCohesion *b = BondBook::of(lmp).pairBonds;
    if (!b)
        endRun(lmp->error, FLERR, std::string(style) + " needs pair_style gran with cohesion bond/nonlinear "
                                                       "(defined before the run)");
    return b;
}

void PairBondsUse::follow(LAMMPS_NS::LAMMPS *lmp, BondNonlinearCohesion *model)
{
    // a model that is gone (a replaced pair style) has no counter left
    BondNonlinearCohesion *current = BondBook::of(lmp).pairBonds;
    if (model_ && model_ == current) (model_->*users_)--;
    model_ = model;
    if (model_) (model_->*users_)++;
}

namespace {

using LAMMPS_NS::LAMMPS;

// ---------------------------------------------------------------- compute
// compute ID group bond/counter [cumulative yes|no]
//
// Global vector of 8: pair bonds created, broken, intact; wall bonds
// created, broken, intact (the 6 of LIGGGHTS-INL); pair and wall bonds
// lost, which vanished with their atoms (lost or deleted) without breaking.
// As in LIGGGHTS-INL, created/broken (and lost) count the events since this
// compute's previous output (`cumulative yes`: since the start of the run
// series, across restart files); intact is the number of intact bonds at the step of the output.
// Summed over all ranks.
class ComputeBondCounter : public LAMMPS_NS::Compute {
public:
    ComputeBondCounter(LAMMPS *lmp, int &iarg, int narg, char **arg) :
        Compute(lmp, iarg, narg, arg), cumulative_(false), lastStep_(-1)
    {
        while (iarg < narg) {
            if (strcmp(arg[iarg], "cumulative") == 0 && iarg + 1 < narg) {
                if (strcmp(arg[iarg + 1], "yes") == 0)
                    cumulative_ = true;
                else if (strcmp(arg[iarg + 1], "no") == 0)
                    cumulative_ = false;
                else
                    error->all(FLERR, "compute bond/counter: cumulative takes yes or no");
                iarg += 2;
            } else {
                endRun(error, FLERR, std::string("compute bond/counter: unknown keyword '") + arg[iarg] +
                                         "' (the only one is: cumulative yes|no)");
            }
        }
        vector_flag = 1;
        size_vector = BondBook::kTotals;
        extvector = 1;
        vector = values_;
        for (int k = 0; k < BondBook::kTotals; k++) values_[k] = reported_[k] = 0.0;
    }

    void init() {}

    void compute_vector()
    {
        invoked_vector = update->ntimestep;
        const int n = BondBook::kTotals;
        double local[n], total[n];
        BondBook &book = BondBook::of(lmp);
        book.refresh(true);
        const long long dropped = book.takeDropped(world);
        if (dropped > 0 && comm->me == 0) error->warning(FLERR, droppedMessage(dropped).c_str());
        // events since the previous output: not those before a restart
        book.localTotals(local, update->ntimestep, cumulative_);
        MPI_Allreduce(local, total, n, MPI_DOUBLE, MPI_SUM, world);
        for (int k = 0; k < n; k++) values_[k] = total[k];
        if (!cumulative_) {
            for (int k : {0, 1, 3, 4, 6, 7}) values_[k] = total[k] - reported_[k];
            if (update->ntimestep != lastStep_)
                for (int k = 0; k < n; k++) reported_[k] = total[k];
            else
                for (int k : {0, 1, 3, 4, 6, 7}) values_[k] = lastValues_[k];
        }
        lastStep_ = update->ntimestep;
        for (int k = 0; k < n; k++) lastValues_[k] = values_[k];
    }

private:
    bool cumulative_;
    bigint lastStep_;
    double values_[BondBook::kTotals], reported_[BondBook::kTotals], lastValues_[BondBook::kTotals];
};

// ------------------------------------------------------------------- fix
// fix ID group bond/breaklog FILE [every N]
//
// One line per broken bond (break_log.h, the same as LAMMPS's): step, atom
// ids (0 for a wall), bond position, mode, sigma and tau of the step that
// broke it and their limits. Rank 0 writes, every N steps (default 100) and
// at the end of each run.
class FixBondBreakLog : public LAMMPS_NS::Fix {
public:
    FixBondBreakLog(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
    {
        std::string wrong = BreakLogFile::words(narg, arg, nevery);
        if (!wrong.empty()) endRun(error, FLERR, "fix bond/breaklog: " + wrong);
        wrong = file_.open(arg[3], comm->me);
        if (!wrong.empty()) endRunOnThisRank(lmp, FLERR, "fix bond/breaklog: " + wrong);
        BondBook::of(lmp).addLogUser();
    }

    ~FixBondBreakLog() { BondBook::of(lmp).removeLogUser(); }

    int setmask() { return LAMMPS_NS::FixConst::END_OF_STEP | LAMMPS_NS::FixConst::POST_RUN; }
    void end_of_step() { flush(); }
    void post_run() { flush(); }

private:
    void flush() { file_.write(BondBook::of(lmp).events(), world); }

    BreakLogFile file_;
};

LAMMPS_NS::Compute *createCounter(LAMMPS *lmp, int iarg, int narg, char **arg)
{
    return new ComputeBondCounter(lmp, iarg, narg, arg);
}

LAMMPS_NS::Fix *createBreakLog(LAMMPS *lmp, int narg, char **arg) { return new FixBondBreakLog(lmp, narg, arg); }

// Modify keeps its style tables private (engine_member.h).
typedef LAMMPS_NS::Compute *(*ComputeCreator)(LAMMPS *, int, int, char **);
typedef LAMMPS_NS::Fix *(*FixCreator)(LAMMPS *, int, char **);
typedef std::map<std::string, ComputeCreator> *LAMMPS_NS::Modify::*ComputeMapMember;
typedef std::map<std::string, FixCreator> *LAMMPS_NS::Modify::*FixMapMember;

}

GRANBOND_ENGINE_MEMBER(ComputeMapTag, ComputeMapMember, &LAMMPS_NS::Modify::compute_map);
GRANBOND_ENGINE_MEMBER(FixMapTag, FixMapMember, &LAMMPS_NS::Modify::fix_map);

void registerBondStyles(LAMMPS_NS::LAMMPS *lmp)
{
    if (!lmp || !lmp->modify) return;
    std::map<std::string, ComputeCreator> *computes = lmp->modify->*member(ComputeMapTag());
    std::map<std::string, FixCreator> *fixes = lmp->modify->*member(FixMapTag());
    if (computes) (*computes)["bond/counter"] = &createCounter;
    if (computes) (*computes)["pair/gran/local/bond"] = &createPairGranLocalBond;
    if (computes) (*computes)["granbond/energy"] = &createGranbondEnergy;
    if (fixes) (*fixes)["bond/breaklog"] = &createBreakLog;
    if (fixes) (*fixes)[atomsFixStyle()] = &createAtomsFix;
    if (fixes) (*fixes)[bondsFixStyle()] = &createBondsFix;
    if (fixes) (*fixes)[wallBondsFixStyle()] = &createWallBondsFix;
    // granbond's property lines are checked before the engine reads them
    if (fixes) checkPropertyLines(*fixes);
    // each LAMMPS constructor re-registers the engine's "gran" selector
    installCombinationCheck();
}

}
}

// Exported (adapter.map): the launcher calls it right after constructing
// LAMMPS, so the styles and the combination check are there before the deck
// runs (with LD_PRELOAD they arrive with the first bond model).
extern "C" __attribute__((visibility("default"))) void granbond_liggghts_register_styles(void *lmp)
{
    granbond::liggghts::registerBondStyles(static_cast<LAMMPS_NS::LAMMPS *>(lmp));
}
