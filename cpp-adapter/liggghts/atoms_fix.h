// LIGGGHTS's `fix granbond/atoms` (fix_granbond_atoms.h), registered with
// the bond styles (registerBondStyles).
#ifndef GRANBOND_LIGGGHTS_ATOMS_FIX_H
#define GRANBOND_LIGGGHTS_ATOMS_FIX_H

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}

namespace granbond {
namespace liggghts {

LAMMPS_NS::Fix *createAtomsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

}
}

#endif
