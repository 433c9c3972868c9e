#include "bond_store_fix.h"
#include "core_message.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "modify.h"

#include <algorithm>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

Fix *createBondsFix(LAMMPS *lmp, int narg, char **arg) { return new FixGranbondBonds(lmp, narg, arg); }

// Input keeps its current command protected in some LAMMPS versions; a
// derived class may name it.
struct InputCommand : Input {
    static char *Input::*field() { return &InputCommand::command; }
};

}

std::string currentCommand(LAMMPS *lmp)
{
    const char *c = lmp->input ? lmp->input->*InputCommand::field() : nullptr;
    return c ? std::string(c) : std::string();
}

void FixGranbondBonds::init()
{
    long long mine = static_cast<long long>(granbond_bond_store_len(store())), all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    if (all > 0 && comm->me == 0 && currentCommand(lmp) == "write_data")
        error->warning(FLERR, "write_data: the " + std::to_string(all) + " bonds of pair_style granbond are not in "
                              "the data file (read_data gives the atoms without them); write_restart and "
                              "read_restart keep them, with their state");
    if (force->pair_match("granbond", 1)) return;
    if (all > 0 && comm->me == 0)
        error->warning(FLERR, "fix granbond/bonds: " + std::to_string(all) + " bonds of pair_style granbond are kept "
                              "with their atoms but do not act under pair_style " +
                              std::string(force->pair_style ? force->pair_style : "none") +
                              "; they act again when pair_style granbond returns");
}

FixGranbondBonds *bondsFix(LAMMPS *lmp)
{
    Modify *modify = lmp->modify;
    int ifix = modify->find_fix(bondsFixId());
    if (ifix < 0) {
        (*modify->fix_map)[bondsFixStyle()] = &createBondsFix;
        modify->add_fix(std::string(bondsFixId()) + " all " + bondsFixStyle());
        ifix = modify->find_fix(bondsFixId());
    }
    FixGranbondBonds *fix = ifix < 0 ? nullptr : dynamic_cast<FixGranbondBonds *>(modify->fix[ifix]);
    if (!fix) lmp->error->all(FLERR, "pair granbond: fix granbond/bonds was deleted or replaced");
    return fix;
}

}
}
