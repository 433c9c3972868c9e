// compute ID group pair/gran/local/bond keyword ...: one row per intact
// pair bond of `cohesion bond/nonlinear` whose atoms are both in the group,
// each bond on one rank; columns by keyword (bond_columns.h), for dump
// local. LIGGGHTS-INL's name for its linear bond's output.
#ifndef GRANBOND_LIGGGHTS_BOND_LOCAL_H
#define GRANBOND_LIGGGHTS_BOND_LOCAL_H

namespace LAMMPS_NS {
class Compute;
class LAMMPS;
}

namespace granbond {
namespace liggghts {

LAMMPS_NS::Compute *createPairGranLocalBond(LAMMPS_NS::LAMMPS *lmp, int iarg, int narg, char **arg);

}
}

#endif
