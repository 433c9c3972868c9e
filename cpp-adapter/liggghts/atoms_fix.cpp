#include "atoms_fix.h"
#include "bond_book.h"
#include "liggghts_engine.h"

#include "fix_contact_history.h"
#include "fix_granbond_atoms.h"
#include "force.h"
#include "pair_gran.h"
#include "update.h"

namespace granbond {
namespace liggghts {

namespace {

// A run's end files nothing: LIGGGHTS files the contacts' records into the
// atoms' partner arrays at each neighbour-list build and at the next run's
// setup (or a write_restart between runs), as it does without granbond. The
// bonds live in the bond store, and a pair's bond bit is a cache the next
// run's setup pass sets again for every listed pair; filing every bonded
// pair's record at each run's end would cost a partner entry and a history
// record a bond in the engine's pages (46 bytes a bond at 1e5 bonds).
class AtomsFix : public FixGranbondAtoms {
public:
    AtomsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : FixGranbondAtoms(lmp, narg, arg) {}

    // LIGGGHTS's setup gives every atom a just-created fix's start value
    // after the setup pass, which has already marked the atoms seen; the
    // values are right without it (0 from the constructor, or restart data).
    void init() { just_created = 0; }

    // Restart files written during a run (`restart N`) take the history
    // from the partner arrays, which LIGGGHTS fills only at neighbour-list
    // builds: filed now, while the list matches the atoms. Between runs the
    // engine files it itself before writing.
    void write_restart(FILE *fp)
    {
        if (update->whichflag != 0) fileRecords();
        FixGranbondAtoms::write_restart(fp);
    }

protected:
    // The bond counters' events over all ranks (bond_book.h), so that
    // `compute bond/counter cumulative yes` goes on across restarts.
    int globalState(double *values)
    {
        double local[BondBook::kTotals];
        BondBook::of(lmp).refresh(false);
        BondBook::of(lmp).localTotals(local, update->ntimestep);
        MPI_Allreduce(local, values, BondBook::kTotals, MPI_DOUBLE, MPI_SUM, world);
        return BondBook::kTotals;
    }
    void restoreGlobalState(const double *values, int n)
    {
        if (n == BondBook::kTotals) BondBook::of(lmp).restoreTotals(values, comm->me == 0);
    }

private:
    // The contacts' records into the partner arrays.
    void fileRecords()
    {
        LAMMPS_NS::FixContactHistory *history = contactHistory();
        if (history) history->pre_exchange();
    }
    // The pair style's fix contact/history, while its lists exist.
    LAMMPS_NS::FixContactHistory *contactHistory()
    {
        LAMMPS_NS::PairGran *pair = static_cast<LAMMPS_NS::PairGran *>(force->pair_match("gran", 0));
        LAMMPS_NS::FixContactHistory *history = pair ? pair->get_fix_history() : 0;
        return history && pair->list && pair->listgranhistory ? history : 0;
    }
};

}

LAMMPS_NS::Fix *createAtomsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) { return new AtomsFix(lmp, narg, arg); }

}
}
