// `cohesion bond`, LIGGGHTS-INL's linear bond (docs/models/bond-linear.md),
// as a LIGGGHTS cohesion model: the `cohesion bond/nonlinear` class with
// INL's names for its parameters and the core's linear law (the bond
// table's row `linear`), its parameters told to serve the linear bond
// before the shared class builds them. What the law does with the
// contact's loads under the bond is the core's
// (granbond_bond_keeps_contact_loads), applied by the shared class.
#ifndef GRANBOND_LIGGGHTS_COHESION_MODEL_BOND_LINEAR_H
#define GRANBOND_LIGGGHTS_COHESION_MODEL_BOND_LINEAR_H

#include "bond_nonlinear_cohesion.h"

namespace granbond {
namespace liggghts {

// Built before the shared cohesion class, so the parameters it builds
// serve the linear bond.
struct ServesLinearBond {
    ServesLinearBond() { BondNonlinearParameters::nextServeLinearBond(); }
};

}
}

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit cohesion id of the style hash (register_combination.h): stock
// Debian ids are 0-8, LIGGGHTS-INL's `cohesion bond` is 14; granbond
// models use >= 32.
static const int COHESION_BOND_LINEAR = 41;

template<>
class CohesionModel<COHESION_BOND_LINEAR> : private granbond::liggghts::ServesLinearBond,
                                              public granbond::liggghts::BondNonlinearCohesion {
public:
    CohesionModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb) :
        granbond::liggghts::ServesLinearBond(),
        granbond::liggghts::BondNonlinearCohesion(lmp, hsetup, cmb)
    {}
};

}
}

#endif
