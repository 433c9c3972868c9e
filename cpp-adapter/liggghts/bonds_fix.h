// LIGGGHTS's fix granbond/bonds: the shared store fix
// (common/fix_granbond_bonds.h), made by cohesion bond/nonlinear for its
// pair bonds (or taken from a restart file), registered with the bond
// styles (registerBondStyles).
#ifndef GRANBOND_LIGGGHTS_BONDS_FIX_H
#define GRANBOND_LIGGGHTS_BONDS_FIX_H

#include "liggghts_engine.h"
#include "fix_granbond_bonds.h"

namespace granbond {
namespace liggghts {

LAMMPS_NS::Fix *createBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

// The fix cohesion bond/nonlinear keeps its pair bonds in: the existing one
// (from read_restart, or an earlier pair style), or a new one.
BondStoreFix *bondsFix(LAMMPS_NS::LAMMPS *lmp);

}
}

#endif
