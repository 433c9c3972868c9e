// `cohesion bond`, LIGGGHTS-INL's linear bond (docs/models/bond-linear.md),
// as a LIGGGHTS cohesion model: the `cohesion bond/nonlinear` class with
// INL's names for its parameters and the core's linear law (the bond
// table's row `linear`). It differs from that class in two things only:
//
// - its parameters serve the linear bond (BondNonlinearParameters, told
//   before the shared class builds them);
// - an overlapping pair's contact loads stay under the bond, the bond's
//   added to them, where the core says so for the type pair
//   (granbond_bond_keeps_contact_loads): the shared class replaces them.
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
        granbond::liggghts::BondNonlinearCohesion(lmp, hsetup, cmb),
        statusAt_(cmb->get_history_offset("bondnonlinear_status"))
    {}

    // The shared class drops the contact's loads of a pair whose bond is
    // intact after its step (and applies the bond's, or has applied them
    // at the atoms): they are added back where the core keeps them.
    void endSurfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        const ForceData contact_i = i_forces, contact_j = j_forces;
        BondNonlinearCohesion::endSurfacesIntersect(sidata, i_forces, j_forces);
        if (!sidata.contact_history || sidata.contact_history[statusAt_] != GB_BOND_STATUS_INTACT) return;
        if (!granbond_bond_keeps_contact_loads(model(sidata.itype, sidata.jtype))) return;
        for (int c = 0; c < 3; c++) {
            i_forces.delta_F[c] += contact_i.delta_F[c];
            i_forces.delta_torque[c] += contact_i.delta_torque[c];
            j_forces.delta_F[c] += contact_j.delta_F[c];
            j_forces.delta_torque[c] += contact_j.delta_torque[c];
        }
    }

private:
    const int statusAt_;   // the bond's status slot in the pair's history
};

}
}

#endif
