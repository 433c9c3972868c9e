#include "bond_store_fix.h"
#include "core_message.h"
#include "error_line.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "modify.h"

#include <algorithm>
#include <cstdlib>
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

void endRun(LAMMPS *lmp, const std::string &message)
{
    flushErrorLine(lmp, message);
    lmp->error->one(FLERR, message);
    std::abort();   // not reached
}

FixGranbondBonds::FixGranbondBonds(LAMMPS *lmp, int narg, char **arg) :
    BondStoreFix(lmp, narg, arg), topology_(narg > 3 && std::strcmp(arg[3], "topology") == 0)
{
    if (narg > 4 || (narg == 4 && !topology_))
        error->all(FLERR, "fix granbond/bonds is made by pair_style granbond and bond_style granbond (its only "
                          "word: topology)");
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
    if (topology_) {
        if (all > 0 && comm->me == 0 && currentCommand(lmp) == "write_data")
            error->warning(FLERR, "write_data: the " + std::to_string(all) + " bonds of bond_style granbond are in the "
                                  "data file's Bonds section, their state is not: read_data starts each at rest at "
                                  "its length then; write_restart and read_restart keep the state");
        if (all > 0 && comm->me == 0 && !force->bond_match("granbond"))
            error->warning(FLERR, "fix granbond/bonds: the state of " + std::to_string(all) + " bonds of bond_style "
                                  "granbond is kept with their atoms but does not act under bond_style " +
                                  std::string(force->bond_style ? force->bond_style : "none"));
        return;
    }
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

FixGranbondBonds *bondsFix(LAMMPS *lmp, bool topology)
{
    Modify *modify = lmp->modify;
    int ifix = modify->find_fix(bondsFixId(topology));
    if (ifix < 0) {
        (*modify->fix_map)[bondsFixStyle()] = &createBondsFix;
        modify->add_fix(std::string(bondsFixId(topology)) + " all " + bondsFixStyle() + (topology ? " topology" : ""));
        ifix = modify->find_fix(bondsFixId(topology));
    }
    FixGranbondBonds *fix = ifix < 0 ? nullptr : dynamic_cast<FixGranbondBonds *>(modify->fix[ifix]);
    if (!fix)
        lmp->error->all(FLERR, std::string(topology ? "bond_style" : "pair") + " granbond: fix granbond/bonds was "
                                                                               "deleted or replaced");
    return fix;
}

}
}
