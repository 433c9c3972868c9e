#include "bond_watch.h"
#include "bond_granbond.h"
#include "bond_store_fix.h"
#include "pair_granbond.h"
#include "bond_columns.h"
#include "local_rows.h"
#include "core_message.h"
#include "run_checks.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

// The home of the bonds this run watches, or an error naming `who`:
// bond_style granbond where it is the bond style, else pair granbond.
BondSource *sourceOf(LAMMPS *lmp, const char *who)
{
    if (auto *bond = dynamic_cast<BondGranbond *>(lmp->force->bond)) return bond;
    PairGranbond *pair = dynamic_cast<PairGranbond *>(lmp->force->pair_match("granbond", 1));
    if (!pair)
        lmp->error->all(FLERR, std::string(who) + " needs bond_style granbond or pair_style granbond (defined before "
                                                  "the run)");
    return pair;
}

// The source this instance follows now (null: none), for a destructor.
BondSource *currentSource(LAMMPS *lmp)
{
    if (!lmp->force) return nullptr;
    if (auto *bond = dynamic_cast<BondGranbond *>(lmp->force->bond)) return bond;
    return dynamic_cast<PairGranbond *>(lmp->force->pair_match("granbond", 1));
}

// Every intact bond of the latest pass: f(index, k) for bond k of each
// index; an error naming `who` if the latest pass is not of this step.
// Calls f(i, j, kind, k, state) for each bond of this rank after the
// latest pass: its owner i (local), its partner j (local or ghost), its
// kind (the type pair's model) and place k in the store, its state.
template<class F>
void forEachBond(LAMMPS *lmp, BondSource *pair, const char *who, F f)
{
    if (!pair->storeCurrent())
        lmp->error->all(FLERR, std::string(who) + ": granbond's bonds have no force pass at step " +
                                   std::to_string(static_cast<long long>(lmp->update->ntimestep)) +
                                   " for the present atoms (use it in a run's output, not between runs)");
    GbBondStore *store = pair->bondStore();
    if (!store) return;
    const size_t n = granbond_bond_store_len(store);
    double state[GRANBOND_BOND_STATE_LEN];
    for (size_t k = 0; k < n; k++) {
        int32_t ends[2];
        int64_t partner = 0;
        if (granbond_bond_store_bond(store, k, ends, &partner, state) != GB_STATUS_OK)
            lmp->error->one(FLERR, std::string(who) + ": " + coreReason());
        const int i = ends[0], j = ends[1];
        f(i, j, pair->bondKind(i, j, k), k, state);
    }
}

class ComputeGranbondAtom : public Compute {
public:
    ComputeGranbondAtom(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg), nmax_(0), count_(nullptr)
    {
        if (narg != 3)
            error->all(FLERR, "compute granbond/atom takes no arguments: compute ID group granbond/atom");
        peratom_flag = 1;
        size_peratom_cols = 0;
    }
    ~ComputeGranbondAtom() override { memory->destroy(count_); }

    void init() override { sourceOf(lmp, "compute granbond/atom"); }

    void compute_peratom() override
    {
        invoked_peratom = update->ntimestep;
        if (atom->nmax > nmax_) {
            memory->destroy(count_);
            nmax_ = atom->nmax;
            memory->create(count_, nmax_, "granbond/atom:count");
            vector_atom = count_;
        }
        const int nlocal = atom->nlocal;
        BondSource *pair = sourceOf(lmp, "compute granbond/atom");
        forEachBond(lmp, pair, "compute granbond/atom", [](int, int, size_t, size_t, const double *) {});
        // the bonds of this rank's atoms, wherever they are stored
        std::vector<uint32_t> counts(static_cast<size_t>(nlocal), 0);
        GbBondStore *store = pair->bondStore();
        const GbAtomIds ids = atomIdsOf(atom);
        if (store && granbond_bond_store_count_atoms(store, counts.data(), counts.size(), &ids) != GB_STATUS_OK)
            error->one(FLERR, std::string("compute granbond/atom: ") + coreReason());
        for (int i = 0; i < nlocal; i++) count_[i] = counts[i];
        const int *mask = atom->mask;
        for (int i = 0; i < nlocal; i++)
            if (!(mask[i] & groupbit)) count_[i] = 0.0;
    }

    double memory_usage() override { return static_cast<double>(nmax_) * sizeof(double); }

private:
    int nmax_;
    double *count_;
};

// ------------------------------------------------------------ counts
// compute ID all bond/granbond: bond_style granbond's twin of compute pair
// granbond's eight counts, summed over ranks (created, broken, intact,
// broken by distance, tension, compression, shear, lost without breaking).
class ComputeBondGranbond : public Compute {
public:
    ComputeBondGranbond(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
    {
        if (narg != 3)
            error->all(FLERR, "compute bond/granbond takes no arguments: compute ID all bond/granbond");
        vector_flag = 1;
        size_vector = 8;
        extvector = 1;
        vector = values_;
    }

    void init() override { bond(); }

    void compute_vector() override
    {
        invoked_vector = update->ntimestep;
        bond()->counts(values_);
    }

private:
    BondGranbond *bond()
    {
        auto *b = dynamic_cast<BondGranbond *>(force->bond);
        if (!b) error->all(FLERR, "compute bond/granbond needs bond_style granbond");
        return b;
    }
    double values_[8] = {0, 0, 0, 0, 0, 0, 0, 0};
};

// ------------------------------------------------------------ per bond
// compute ID group granbond/local keyword ...: one row per intact bond
// whose atoms are both in the group, each bond on one rank; columns by
// keyword (bond_columns.h).
class ComputeGranbondLocal : public Compute {
public:
    ComputeGranbondLocal(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
    {
        const std::string wrong = columns_.parse(narg - 3, arg + 3);
        if (!wrong.empty()) error->all(FLERR, "compute granbond/local: " + wrong);
        local_flag = 1;
        size_local_rows = 0;
        size_local_cols = columns_.size() == 1 ? 0 : static_cast<int>(columns_.size());
    }
    ~ComputeGranbondLocal() override
    {
        listen(nullptr);
    }

    void init() override { listen(sourceOf(lmp, "compute granbond/local")); }

    void compute_local() override
    {
        invoked_local = update->ntimestep;
        BondSource *pair = sourceOf(lmp, "compute granbond/local");
        const int *mask = atom->mask;
        const size_t ncols = columns_.size();
        std::vector<double> &rows = rows_.values;
        rows.clear();
        std::vector<double> row(ncols);
        double record[GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN];
        const std::vector<GbBondOutput> &outs = pair->bondOutputs();
        const bool energies = columns_.wantsEnergy();
        const GbAtomArrays arrays = pair->atomArrays();
        std::vector<double> energy(granbond_bond_energy_field_count(), 0.0);
        forEachBond(lmp, pair, "compute granbond/local", [&](int i, int j, size_t kind, size_t k, const double *state) {
            if (!(mask[i] & groupbit) || !(mask[j] & groupbit)) return;
            // the record the core's fields read: the state, then the loads
            // of the latest force pass
            std::copy(state, state + GRANBOND_BOND_STATE_LEN, record);
            GbBondOutput none;
            std::memset(&none, 0, sizeof none);
            const GbBondOutput &o = k < outs.size() ? outs[k] : none;
            const int lo = atom->tag[i] < atom->tag[j] ? i : j, hi = lo == i ? j : i;
            if ((energies && granbond_bond_store_bond_energy(pair->bondStore(), pair->bondModels(), pair->bondKinds(),
                                                             &arrays, k, energy.data()) != GB_STATUS_OK) ||
                granbond_bond_output_store(&o, record + GRANBOND_BOND_STATE_LEN) != GB_STATUS_OK ||
                columns_.row(pair->bondModel(kind), record, static_cast<double>(atom->tag[i]),
                             static_cast<double>(atom->tag[j]), atom->x[i], atom->x[j], row.data(),
                             energy.data()) != GB_STATUS_OK)
                error->one(FLERR, "compute granbond/local: atoms " + std::to_string(static_cast<long long>(atom->tag[lo])) +
                                      " and " + std::to_string(static_cast<long long>(atom->tag[hi])) + ": " +
                                      coreReason());
            rows.insert(rows.end(), row.begin(), row.end());
        });
        rows_.publish(size_local_cols, size_local_rows, vector_local, array_local);
    }

    double memory_usage() override { return rows_.bytes(); }

private:
    // Follows `pair` from now on (null: none); the pair keeps its bonds'
    // outputs only while a compute follows it.
    void listen(BondSource *pair)
    {
        BondSource *current = currentSource(lmp);
        const int energy = columns_.wantsEnergy() ? 1 : 0;
        if (pair_ && pair_ == current) {
            pair_->bondOutputUsers--;
            pair_->energyOutputUsers -= energy;
        }
        pair_ = pair;
        if (pair_) {
            pair_->bondOutputUsers++;
            pair_->energyOutputUsers += energy;
        }
    }

    BondSource *pair_ = nullptr;

    BondColumns columns_;
    LocalRows rows_;
};

// ------------------------------------------------------------ break log
// fix ID group bond/breaklog FILE [every N]: LIGGGHTS's break log
// (break_log.h) for pair granbond. The group is ignored, as there.
class FixBondBreakLog : public Fix {
public:
    FixBondBreakLog(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), pair_(nullptr)
    {
        std::string wrong = BreakLogFile::words(narg, arg, nevery);
        if (!wrong.empty()) error->all(FLERR, "fix bond/breaklog: " + wrong);
        wrong = file_.open(arg[3], comm->me);
        if (!wrong.empty()) error->one(FLERR, "fix bond/breaklog: " + wrong);
    }
    ~FixBondBreakLog() override { listen(nullptr); }

    int setmask() override { return FixConst::END_OF_STEP | FixConst::POST_RUN; }

    void init() override { listen(sourceOf(lmp, "fix bond/breaklog")); }

    // every step: the events leave the pair (nevery only paces the writing)
    void end_of_step() override
    {
        take();
        if (update->ntimestep % nevery == 0) file_.write(events_, world);
    }
    void post_run() override
    {
        take();
        file_.write(events_, world);
    }

private:
    // Follows `pair` from now on (null: none); the pair keeps break events
    // only while a log follows it.
    void listen(BondSource *pair)
    {
        // at the instance's end the styles are gone before the fixes
        BondSource *current = currentSource(lmp);
        if (pair_ && pair_ == current) pair_->breakLogUsers--;
        pair_ = pair;
        if (pair_) pair_->breakLogUsers++;
    }
    void take()
    {
        if (!pair_) return;
        std::vector<BreakEvent> &e = pair_->breakEvents();
        events_.insert(events_.end(), e.begin(), e.end());
        if (pair_->breakLogUsers <= 1) e.clear();
    }

    BreakLogFile file_;
    BondSource *pair_;
    std::vector<BreakEvent> events_;
};

}

Compute *newComputeGranbondAtom(LAMMPS *lmp, int narg, char **arg) { return new ComputeGranbondAtom(lmp, narg, arg); }
Compute *newComputeBondGranbond(LAMMPS *lmp, int narg, char **arg)
{
    return new ComputeBondGranbond(lmp, narg, arg);
}
Compute *newComputeGranbondLocal(LAMMPS *lmp, int narg, char **arg)
{
    return new ComputeGranbondLocal(lmp, narg, arg);
}
Fix *newFixBondBreakLog(LAMMPS *lmp, int narg, char **arg) { return new FixBondBreakLog(lmp, narg, arg); }

}
}
