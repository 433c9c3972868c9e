#include "bonds_fix.h"
#include "bond_book.h"
#include "core_bridge.h"

#include <string>

namespace granbond {
namespace liggghts {

namespace {

class BondsFix : public BondStoreFix {
public:
    BondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : BondStoreFix(lmp, narg, arg) {}

    // LIGGGHTS's setup gives every atom a just-created fix's start value
    // (set_arrays) after the setup pass, which would drop the bonds it
    // formed or linked; the store is right without it.
    // A run without cohesion bond/nonlinear on the pairs: the bonds wait,
    // and the deck is told.
    void init()
    {
        just_created = 0;
        long long mine = static_cast<long long>(granbond_bond_store_len(store())), all = 0;
        MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
        if (all > 0 && comm->me == 0 && !BondBook::of(lmp).pairBonds)
            error->warning(FLERR, ("fix granbond/bonds: " + std::to_string(all) +
                                   " bonds of cohesion bond/nonlinear are kept with their atoms but do not act "
                                   "under this pair style; they act again when a pair style with cohesion "
                                   "bond/nonlinear returns")
                                      .c_str());
    }
};

}

LAMMPS_NS::Fix *createBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) { return new BondsFix(lmp, narg, arg); }

BondStoreFix *bondsFix(LAMMPS_NS::LAMMPS *lmp)
{
    BondStoreFix *fix = dynamic_cast<BondStoreFix *>(fixOrNew(lmp, bondsFixId(), bondsFixStyle()));
    if (!fix) endRun(lmp->error, FLERR, "cohesion bond/nonlinear: fix granbond/bonds was deleted or replaced");
    return fix;
}

}
}
