// What both adapters' passes over the bond store share: the engine's atoms
// as the core reads them, the link after a list build, the chunks of a
// pass stepped with their loads added to the atoms by the core (the
// adapters say where: ghost rows, LIGGGHTS's relaxation factor). The
// adapters find the pairs in their own lists.
#ifndef GRANBOND_STORE_PASS_H
#define GRANBOND_STORE_PASS_H

#include "core_message.h"
#include "fix_granbond_bonds.h"
#include "granbond.h"

#include <string>
#include <vector>

namespace granbond {

// A rank's per-atom arrays (local and ghost) as the core reads them.
template <class Atom>
GbAtomArrays atomArraysOf(const Atom *atom)
{
    const bool any = atom->nmax > 0;
    GbAtomArrays a;
    a.x = any ? atom->x[0] : nullptr;
    a.v = any ? atom->v[0] : nullptr;
    a.omega = any ? atom->omega[0] : nullptr;
    a.radius = atom->radius;
    a.count = static_cast<size_t>(atom->nlocal + atom->nghost);
    return a;
}

// The kinematics of the pair (i, j) of local or ghost atoms.
template <class Atom>
void pairKinematicsOf(const Atom *atom, int i, int j, GbPairKinematics &k)
{
    for (int c = 0; c < 3; c++) {
        k.x_i[c] = atom->x[i][c];
        k.x_j[c] = atom->x[j][c];
        k.v_i[c] = atom->v[i][c];
        k.v_j[c] = atom->v[j][c];
        k.w_i[c] = atom->omega[i][c];
        k.w_j[c] = atom->omega[j][c];
    }
    k.radius_i = atom->radius[i];
    k.radius_j = atom->radius[j];
}

// The engine's per-atom load sums as the core adds to them: a ghost
// partner's loads in `ghostRows` (6 doubles a ghost) unless it is null,
// each atom's loads scaled by `relax[i]` unless it is null.
template <class Atom>
GbAtomLoads atomLoadsOf(Atom *atom, double *ghostRows, const double *relax)
{
    const bool any = atom->nmax > 0;
    GbAtomLoads l;
    l.force = any ? atom->f[0] : nullptr;
    l.torque = any ? atom->torque[0] : nullptr;
    l.count = static_cast<size_t>(atom->nlocal + atom->nghost);
    l.nlocal = static_cast<size_t>(atom->nlocal);
    l.ghost_rows = ghostRows;
    l.relax = relax;
    return l;
}

// Steps the chunks of the pass not stepped yet; the core adds their loads
// to `loads`. Where `perBond` (the virial) or `kept` asks for the outputs,
// they come back chunk by chunk: perBond(i, j, out) for each bond (its
// owner i, its partner j), each output kept in `kept` if it is not null;
// else the pass is one call. On a core failure, failed(i, j, reason) with
// the bond's atoms (-1 if unknown); it must not return.
template <class Atom, class PerBond, class Failed>
void stepStoreChunks(GbBondStore *store, const GbBondModel *const *models, size_t nkinds, const Atom *atom,
                     const GbAtomIds &ids, const GbAtomLoads &loads, std::vector<GbBondOutput> *kept, bool wantPerBond,
                     PerBond perBond, Failed failed)
{
    const GbAtomArrays arrays = atomArraysOf(atom);
    const auto fail = [&](size_t bad) {
        int32_t e[2] = {-1, -1};
        int64_t partner = 0;
        double state[GRANBOND_BOND_STATE_LEN];
        const std::string why = coreReason();
        if (granbond_bond_store_bond(store, bad, e, &partner, state) != GB_STATUS_OK) e[0] = e[1] = -1;
        failed(e[0], e[1], why);
    };
    if (!wantPerBond && !kept) {
        size_t n = 0, bad = 0;
        if (granbond_bond_store_step_rest(store, models, nkinds, &arrays, &ids, &loads, &n, &bad) != GB_STATUS_OK)
            fail(bad);
        return;
    }
    int32_t ends[2 * GRANBOND_BOND_STORE_CHUNK];
    GbBondOutput outs[GRANBOND_BOND_STORE_CHUNK];
    for (;;) {
        size_t n = 0, bad = 0;
        if (granbond_bond_store_step_next(store, models, nkinds, &arrays, &ids, &loads, ends, outs, &n, &bad) !=
            GB_STATUS_OK)
            fail(bad);
        if (n == 0) return;
        if (wantPerBond)
            for (size_t k = 0; k < n; k++) perBond(ends[2 * k], ends[2 * k + 1], outs[k]);
        if (kept) kept->insert(kept->end(), outs, outs + n);
    }
}

// A pair the pair loop proposes at a creation step (or, with `now`, one
// that bonds whatever the step: a LIGGGHTS `bonded yes` clump's): created
// by this rank if it owns the pair (`formed` set), or, newton off, taken as
// bonded where the owning rank creates it. `bonded`: a bond from now on.
template <class Atom>
GbStatus proposePair(GbBondStore *store, const GbBondModel *model, uint16_t kind, const Atom *atom, int i, int j,
                     bool newtonOff, int64_t step, bool now, bool &bonded, bool &formed)
{
    const auto *tag = atom->tag;
    const int nlocal = atom->nlocal;
    const int owner = granbond_bond_store_creates_here(i < nlocal, j < nlocal, tag[i], tag[j], newtonOff);
    GbPairKinematics k;
    int32_t made = 0;
    GbStatus s = GB_STATUS_OK;
    if (owner < 0) {
        pairKinematicsOf(atom, i, j, k);
        s = granbond_bond_store_would_create(store, model, static_cast<size_t>(i), static_cast<size_t>(j), &k, step,
                                             &made);
    } else {
        const int o = owner == 0 ? i : j, p = owner == 0 ? j : i;
        pairKinematicsOf(atom, o, p, k);
        s = granbond_bond_store_try_create(store, model, kind, static_cast<size_t>(o), static_cast<size_t>(p), tag[o],
                                           tag[p], &k, step, &made);
        if (s == GB_STATUS_OK && !made && now)
            s = granbond_bond_store_create_now(store, model, kind, static_cast<size_t>(o), static_cast<size_t>(p),
                                               tag[o], tag[p], &k, &made);
        formed = formed || made;
    }
    bonded = made != 0;
    return s;
}

// Finds every bond's atoms again after a list build
// (granbond_bond_store_link): `kinds` the bond kind of each type pair (-1
// none), `reach` how far the ghost atoms reach.
template <class Atom>
GbStatus linkStore(GbBondStore *store, const Atom *atom, const std::vector<int32_t> &kinds, int ntypes,
                   double reach, GbLinkReport &report)
{
    GbStoreAtoms sa;
    sa.ids = atomIdsOf(atom);
    sa.nlocal = static_cast<size_t>(atom->nlocal);
    sa.x = atom->nmax > 0 ? atom->x[0] : nullptr;
    sa.types = atom->type;
    sa.reach = reach;
    return granbond_bond_store_link(store, &sa, kinds.data(), static_cast<size_t>(ntypes), &report);
}

}

#endif
