// What a LAMMPS deck watches of pair granbond's bonds (bond_watch.cpp):
//
//   compute ID group granbond/atom               per atom: its intact bonds
//   compute ID group granbond/local kw ...       per bond: named fields (dump local)
//   fix ID group bond/breaklog FILE [every N]    one line per broken bond
//
// The global counts are `compute ID all pair granbond` (pair_granbond.cpp).
#ifndef GRANBOND_LAMMPS_BOND_WATCH_H
#define GRANBOND_LAMMPS_BOND_WATCH_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace granbond {
namespace lammps {

// Adds the styles above to this instance's tables (the launcher, after
// constructing LAMMPS and after every `clear`).
void registerWatchStyles(LAMMPS_NS::LAMMPS *lmp);

// The same styles for `plugin load` (lammpsplugin_init's arguments, and
// the LAMMPS version the plugins were built for).
void loadWatchPlugins(void *lmp, void *handle, void *regfunc, const char *version);

}
}

#endif
