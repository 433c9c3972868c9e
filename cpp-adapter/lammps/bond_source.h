// What the bond outputs read (bond_watch.cpp), from either home of granbond's
// bonds in LAMMPS: pair_style granbond (bonds formed by distance, kind = the
// type pair) or bond_style granbond (the topology's bonds, kind = the bond
// type). Both keep their bonds in the core's store; this names the store,
// the model of a kind, and what the latest pass left.
#ifndef GRANBOND_LAMMPS_BOND_SOURCE_H
#define GRANBOND_LAMMPS_BOND_SOURCE_H

#include "break_log.h"
#include "granbond.h"

#include <vector>

namespace granbond {
namespace lammps {

class BondSource {
public:
    // The store of this rank (null before the first run).
    virtual GbBondStore *bondStore() const = 0;
    // The model of bond `kind`.
    virtual const GbBondModel *bondModel(size_t kind) const = 0;
    // The kind of bond k of the store, between its owner i and partner j.
    virtual size_t bondKind(int i, int j, size_t k) const = 0;
    // Whether the latest pass is of this step and these atoms.
    virtual bool storeCurrent() const = 0;
    // Each bond's output of the latest force pass, in store order (kept
    // while bondOutputUsers > 0).
    virtual const std::vector<GbBondOutput> &bondOutputs() const = 0;
    // The bonds broken in force passes (kept while breakLogUsers > 0).
    virtual std::vector<BreakEvent> &breakEvents() = 0;
    // The models by kind and the atoms' arrays, as the store's calls take
    // them (a bond's energies).
    virtual const GbBondModel *const *bondModels() const = 0;
    virtual size_t bondKinds() const = 0;
    virtual GbAtomArrays atomArrays() const = 0;
    int breakLogUsers = 0;
    int bondOutputUsers = 0;
    // compute granbond/local asking for a bond's dissipated energies: the
    // store keeps each bond's share while it is non-zero.
    int energyOutputUsers = 0;

protected:
    // never deleted through this interface: the styles own themselves
    ~BondSource() = default;
};

}
}

#endif
