// The chunks of a pass of the core's bond store stepped and their loads
// added to the atoms, for both homes of granbond's bonds in LAMMPS (pair
// and bond style): both atoms' forces and torques; a ghost partner's on the
// ghost itself where the engine sums ghosts' loads to their owners
// (`engineSums`), else in `ghostLoads` (6 doubles a ghost: force, torque)
// for the store's fix to send back.
#ifndef GRANBOND_LAMMPS_STORE_PASS_H
#define GRANBOND_LAMMPS_STORE_PASS_H

#include "bond_store_fix.h"
#include "core_message.h"
#include "granbond.h"
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
    const GbAtomArrays arrays = atomArraysOf(atom);
    const GbAtomIds ids = atomIdsOf(atom);
    int32_t ends[2 * GRANBOND_BOND_STORE_CHUNK];
    GbBondOutput outs[GRANBOND_BOND_STORE_CHUNK];
    const bool any = atom->nmax > 0;
    double *const f0 = any ? atom->f[0] : nullptr, *const t0 = any ? atom->torque[0] : nullptr;
    const int nlocal = atom->nlocal;
    for (;;) {
        size_t n = 0, bad = 0;
        if (granbond_bond_store_step_next(store, models.data(), models.size(), &arrays, &ids, ends, outs, &n,
                                          &bad) != GB_STATUS_OK) {
            int32_t e[2] = {-1, -1};
            int64_t partner = 0;
            double state[GRANBOND_BOND_STATE_LEN];
            const std::string why = coreReason();
            if (granbond_bond_store_bond(store, bad, e, &partner, state) == GB_STATUS_OK && e[0] >= 0)
                failed(e[0], e[1], why);
            failed(-1, -1, why);
        }
        if (n == 0) break;
        for (size_t k = 0; k < n; k++) {
            const int i = ends[2 * k], j = ends[2 * k + 1];
            const GbBondOutput &o = outs[k];
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
        }
        if (keep) keep->insert(keep->end(), outs, outs + n);
    }
}

}
}

#endif
