// compute ID all granbond/energy: the energy budget of the pair bonds of
// `cohesion bond/nonlinear`, summed over the ranks (bond_energy.cpp).
#ifndef GRANBOND_LIGGGHTS_BOND_ENERGY_H
#define GRANBOND_LIGGGHTS_BOND_ENERGY_H

namespace LAMMPS_NS {
class Compute;
class LAMMPS;
}

namespace granbond {
namespace liggghts {

LAMMPS_NS::Compute *createGranbondEnergy(LAMMPS_NS::LAMMPS *lmp, int iarg, int narg, char **arg);

}
}

#endif
