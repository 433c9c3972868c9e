// LAMMPS's fix granbond/bonds: the shared store fix (common/fix_granbond_bonds.h)
// with what LAMMPS adds at a run's start: a write_data that leaves the
// bonds out, and a run under another pair style, are told to the deck.
// pair granbond makes it (or takes the one read_restart brought back) and
// is its only user.
#ifndef GRANBOND_LAMMPS_BOND_STORE_FIX_H
#define GRANBOND_LAMMPS_BOND_STORE_FIX_H

#include "fix_granbond_bonds.h"

#include <string>

namespace granbond {
namespace lammps {

class FixGranbondBonds : public BondStoreFix {
public:
    FixGranbondBonds(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : BondStoreFix(lmp, narg, arg) {}

    // A run under another pair style: the bonds wait, and the deck is told.
    void init() override;
};

// The input command LAMMPS carries out now ("run", "write_data", ...).
std::string currentCommand(LAMMPS_NS::LAMMPS *lmp);

// Registers the style with LAMMPS (once) and returns the fix pair granbond
// uses: the existing one (from read_restart, or an earlier run), or a new one.
FixGranbondBonds *bondsFix(LAMMPS_NS::LAMMPS *lmp);

}
}

#endif
