// What a LAMMPS deck watches of pair granbond's bonds (bond_watch.cpp):
//
//   compute ID group granbond/atom               per atom: its intact bonds
//   compute ID group granbond/local kw ...       per bond: named fields (dump local)
//   fix ID group bond/breaklog FILE [every N]    one line per broken bond
//
//   compute ID all bond/granbond                 bond_style granbond's counts
//
// The first three and the log follow bond_style granbond where it is the
// bond style, else pair_style granbond, whose global counts are `compute ID
// all pair granbond` (pair_granbond.cpp).
#ifndef GRANBOND_LAMMPS_BOND_WATCH_H
#define GRANBOND_LAMMPS_BOND_WATCH_H

namespace LAMMPS_NS {
class LAMMPS;
class Compute;
class Fix;
}

namespace granbond {
namespace lammps {

// The styles above, made as LAMMPS makes a style from its command's
// arguments (registered by plugin.cpp).
LAMMPS_NS::Compute *newComputeGranbondAtom(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
LAMMPS_NS::Compute *newComputeBondGranbond(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
LAMMPS_NS::Compute *newComputeGranbondLocal(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
LAMMPS_NS::Fix *newFixBondBreakLog(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

}
}

#endif
