// The chunks of a pass of the core's bond store stepped and their loads
// added to the atoms, for both homes of granbond's bonds in LAMMPS (pair
// and bond style): both atoms' forces and torques; a ghost partner's on the
// ghost itself where the engine sums ghosts' loads to their owners
// (`engineSums`), else in `ghostLoads` (6 doubles a ghost: force, torque)
// for the store's fix to send back.
#ifndef GRANBOND_LAMMPS_ATOM_LOADS_H
#define GRANBOND_LAMMPS_ATOM_LOADS_H

#include "bond_store_fix.h"
#include "store_pass.h"
#include "vector_adds.h"

#include "atom.h"

#include <string>
#include <vector>

namespace granbond {
namespace lammps {

// `tally(i, j, force_i)` is called for each bond stepped (the virial);
// `failed(i, j, why)` for a bond that could not be stepped (i < 0: not
// known), and must not return; `keep`, when not null, receives every
// output in store order.
template<class Tally, class Failed>
void stepChunks(LAMMPS_NS::Atom *atom, GbBondStore *store, const std::vector<GbBondModel *> &models,
                bool engineSums, double *ghostLoads, std::vector<GbBondOutput> *keep, Tally tally, Failed failed)
{
    const bool any = atom->nmax > 0;
    double *const f0 = any ? atom->f[0] : nullptr, *const t0 = any ? atom->torque[0] : nullptr;
    const int nlocal = atom->nlocal;
    stepStoreChunks(
        store, models.data(), models.size(), atom, atomIdsOf(atom), keep,
        // (by value: the pointers and switches stay in registers through
        // the stores to the atoms)
        [=](int i, int j, const GbBondOutput &o) mutable {
            add3(f0 + 3 * static_cast<size_t>(i), o.force_i);
            add3(t0 + 3 * static_cast<size_t>(i), o.torque_i);
            if (j < nlocal || engineSums) {
                subtract3(f0 + 3 * static_cast<size_t>(j), o.force_i);
                add3(t0 + 3 * static_cast<size_t>(j), o.torque_j);
            } else {
                double *g = ghostLoads + 6 * static_cast<size_t>(j - nlocal);
                subtract3(g, o.force_i);
                add3(g + 3, o.torque_j);
            }
            tally(i, j, o.force_i);
        },
        failed);
}

}
}

#endif
