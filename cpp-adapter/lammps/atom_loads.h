// The chunks of a pass of the core's bond store stepped, for both homes of
// granbond's bonds in LAMMPS (pair and bond style); the core adds their
// loads to both atoms' forces and torques: a ghost partner's on the ghost
// itself where the engine sums ghosts' loads to their owners
// (`engineSums`), else in `ghostLoads` (6 doubles a ghost: force, torque)
// for the store's fix to send back.
#ifndef GRANBOND_LAMMPS_ATOM_LOADS_H
#define GRANBOND_LAMMPS_ATOM_LOADS_H

#include "bond_store_fix.h"
#include "store_pass.h"

#include "atom.h"

#include <string>
#include <vector>

namespace granbond {
namespace lammps {

// With `virial`, `tally(i, j, force_i)` is called for each bond stepped;
// `failed(i, j, why)` for a bond that could not be stepped (i < 0: not
// known), and must not return; `keep`, when not null, receives every
// output in store order.
template<class Tally, class Failed>
void stepChunks(LAMMPS_NS::Atom *atom, GbBondStore *store, const std::vector<GbBondModel *> &models,
                bool engineSums, double *ghostLoads, std::vector<GbBondOutput> *keep, bool virial, Tally tally,
                Failed failed)
{
    const GbAtomLoads loads = atomLoadsOf(atom, engineSums ? nullptr : ghostLoads, nullptr);
    stepStoreChunks(
        store, models.data(), models.size(), atom, atomIdsOf(atom), loads, keep, virial,
        [&](int i, int j, const GbBondOutput &o) { tally(i, j, o.force_i); }, failed);
}

}
}

#endif
