// `cohesion bond/nonlinear` as a LIGGGHTS cohesion model: the template slot
// the engine's GranStyle<> combinations instantiate. All behaviour lives in
// BondNonlinearCohesion (compiled once); this only gives it an id.
#ifndef GRANBOND_LIGGGHTS_COHESION_MODEL_BOND_NONLINEAR_H
#define GRANBOND_LIGGGHTS_COHESION_MODEL_BOND_NONLINEAR_H

#include "bond_nonlinear_cohesion.h"

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit cohesion id of the style hash. Stock Debian ids are 0-8 and
// LIGGGHTS-INL uses 15 for its own bond/nonlinear; granbond models use >= 32.
static const int COHESION_BOND_NONLINEAR = 40;

template<>
class CohesionModel<COHESION_BOND_NONLINEAR> : public granbond::liggghts::BondNonlinearCohesion {
public:
    CohesionModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb) :
        granbond::liggghts::BondNonlinearCohesion(lmp, hsetup, cmb)
    {}
};

}
}

#endif
