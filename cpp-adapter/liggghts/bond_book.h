// Bond bookkeeping shared by the bond models of one LAMMPS instance and the
// deck-level tools that report it (`compute bond/counter`,
// `fix bond/breaklog`): event counters, the intact-bond count of the latest
// force pass, and the break events not yet written.
//
// Counting rule under MPI: a pair whose atoms sit on two ranks is computed
// on both (half list, newton off); each event and each intact bond is
// counted only where the pair is seen from its lower-tag atom or where both
// atoms are owned (`countsHere`). Particle-wall bonds are computed only on
// the rank that owns the particle. Values are per rank; the tools sum them.
#ifndef GRANBOND_LIGGGHTS_BOND_BOOK_H
#define GRANBOND_LIGGGHTS_BOND_BOOK_H

#include "liggghts_engine.h"
#include "break_log.h"

#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

class BondNonlinearCohesion;

// Counters of one bond model instance (the pair style's, or one wall fix's).
struct BondTally {
    bool wall = false;
    long long created = 0;     // events on this rank since the start of the run series
    long long broken = 0;
    long long lost = 0;        // bonds that vanished with their atoms (counted on rank 0)
    long long intact = 0;      // intact bonds seen in the force pass `pass`
    long long pass = -1;       // 2*ntimestep + setupflag of that pass
    bigint passStep = -1;
    // A model whose counts live in a store (wall bonds) takes them from it
    // here before they are read; `collective`: every rank calls it, and
    // losses are told.
    void (*refresh)(void *owner, bool collective) = nullptr;
    void *owner = nullptr;
    // Takes a store's counts (the core's row: broken all modes, lost all
    // causes).
    void take(const GbStoreCounts &c);
};

class BondBook {
public:
    static BondBook &of(LAMMPS_NS::LAMMPS *lmp);

    void add(BondTally *t);
    // Forgets a model whose fix or pair style was deleted (`unfix` of a
    // wall). Its events stay counted; its intact bonds, gone with it, count
    // as lost.
    void remove(BondTally *t);
    // The bonds remove() counted as lost since the previous call, over all
    // ranks (collective).
    long long takeDropped(MPI_Comm world);

    // Starts counting intact bonds of `t` for the current pass if it is a new one.
    // Inline: called for every bond in every force pass.
    void beginPassIfNew(BondTally &t, LAMMPS_NS::Update *update)
    {
        const long long pass = 2 * static_cast<long long>(update->ntimestep) + (update->setupflag ? 1 : 0);
        if (pass == t.pass) return;
        t.pass = pass;
        t.passStep = update->ntimestep;
        t.intact = 0;
    }

    // Each model's counts taken from its store where it keeps them there
    // (BondTally::refresh), before they are read.
    void refresh(bool collective);

    // Sums over this rank's models: [pair created, broken, intact, wall created, broken, intact,
    // pair lost, wall lost]. Intact counts only of models whose latest pass is the current step.
    static const int kTotals = 8;
    // `restored`: with the counts of the runs before the restart file.
    void localTotals(double out[kTotals], bigint step, bool restored = true) const;
    // The event counts (created, broken, lost; not intact) over all ranks
    // that a restart file brings back: rank 0 adds them to its totals, so
    // cumulative counts go on across restarts.
    void restoreTotals(const double totals[kTotals], bool root);

    // The pair style's bond model, for per-bond output (compute
    // pair/gran/local/bond) and fix granbond/atoms; null without one.
    BondNonlinearCohesion *pairBonds = nullptr;

    bool logging() const { return logUsers_ > 0; }
    void addLogUser() { logUsers_++; }
    void removeLogUser() { logUsers_--; }
    void record(const BreakEvent &e) { events_.push_back(e); }
    std::vector<BreakEvent> &events() { return events_; }

private:
    std::vector<BondTally *> tallies_;
    BondTally retiredPair_, retiredWall_;   // the counts of removed models
    long long dropped_ = 0;
    LAMMPS_NS::LAMMPS *lmp_ = nullptr;
    std::vector<BreakEvent> events_;
    int logUsers_ = 0;
    double restored_[kTotals] = {0, 0, 0, 0, 0, 0, 0, 0};
};

// A compute's hold on the pair style's bond model: it counts itself in one
// of the model's user counters (`bondOutputUsers`, `energyUsers`), which
// make the model keep what the compute reads, while it follows the model.
class PairBondsUse {
public:
    explicit PairBondsUse(int BondNonlinearCohesion::*users) : users_(users) {}
    // The pair style's bond model; ends the run without one, naming `style`.
    BondNonlinearCohesion *need(LAMMPS_NS::LAMMPS *lmp, const char *style) const;
    // Follows `model` from now on (null: none).
    void follow(LAMMPS_NS::LAMMPS *lmp, BondNonlinearCohesion *model);

private:
    int BondNonlinearCohesion::*users_;
    BondNonlinearCohesion *model_ = nullptr;
};

// The warning for bonds dropped with their model (takeDropped).
std::string droppedMessage(long long dropped);

// Adds `compute bond/counter`, `compute pair/gran/local/bond` and
// `fix bond/breaklog` to this instance's
// style tables (idempotent). Called when a bond model is constructed, and by
// the launcher right after LAMMPS is constructed.
void registerBondStyles(LAMMPS_NS::LAMMPS *lmp);

}
}

#endif
