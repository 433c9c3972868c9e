// LAMMPS's fix granbond/bonds: the shared store fix (common/fix_granbond_bonds.h)
// with what LAMMPS adds at a run's start: a write_data that leaves the
// bonds (or their state) out, and a run under another style, are told to
// the deck. pair granbond makes it (or takes the one read_restart brought
// back); bond_style granbond has one of its own (`fix ID all
// granbond/bonds topology`), whose bonds the topology names.
#ifndef GRANBOND_LAMMPS_BOND_STORE_FIX_H
#define GRANBOND_LAMMPS_BOND_STORE_FIX_H

#include "fix_granbond_bonds.h"

#include <string>

namespace granbond {
namespace lammps {

class FixGranbondBonds : public BondStoreFix {
public:
    FixGranbondBonds(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

    // A run under another pair (bond) style: the bonds wait, and the deck
    // is told.
    void init() override;

private:
    bool topology_;   // the bonds of bond_style granbond
};

// The fix's ID, as pair granbond (or, `topology`, bond_style granbond)
// creates it.
inline const char *bondsFixId(bool topology = false)
{
    return topology ? "GRANBOND_TOPOLOGY_BONDS" : granbond::bondsFixId();
}

// Ends the run on this rank with `message`, written to the screen and the
// log first (error->one aborts without flushing them).
[[noreturn]] void endRun(LAMMPS_NS::LAMMPS *lmp, const std::string &message);

// The input command LAMMPS carries out now ("run", "write_data", ...).
std::string currentCommand(LAMMPS_NS::LAMMPS *lmp);

// Registers the style with LAMMPS (once) and returns the fix pair granbond
// (or, `topology`, bond_style granbond) uses: the existing one (from
// read_restart, or an earlier run), or a new one.
FixGranbondBonds *bondsFix(LAMMPS_NS::LAMMPS *lmp, bool topology = false);

}
}

#endif
