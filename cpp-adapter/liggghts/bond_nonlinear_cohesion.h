// The engine-facing half of `cohesion bond/nonlinear`: history slots, and per
// pair (or particle-wall contact) one call into the core, whose forces and
// torques replace the contact model's while the bond is intact (spec "Bond and
// contact together"). No physics here: see rust-core.
//
// Compiled once (bond_nonlinear_cohesion.cpp); the CohesionModel<> template
// specialisation in cohesion_model_bond_nonlinear.h only inherits from it.
#ifndef GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H
#define GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H

#include "bond_nonlinear_parameters.h"

namespace granbond {
namespace liggghts {

using LIGGGHTS::ContactModels::ForceData;
using LIGGGHTS::ContactModels::SurfacesCloseData;
using LIGGGHTS::ContactModels::SurfacesIntersectData;

class BondNonlinearCohesion : public LIGGGHTS::ContactModels::CohesionModelBase {
public:
    BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                          LIGGGHTS::ContactModels::ContactModelBase *cmb);

    void registerSettings(::Settings &settings) { parameters_.registerSettings(settings); }
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *) {}
    void connectToProperties(::PropertyRegistry &registry) { parameters_.connectToProperties(registry); }
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

    // Overlapping spheres: the bond acts in endSurfacesIntersect, after the
    // normal, tangential and rolling models have added their forces.
    void surfacesIntersect(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endSurfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces);

private:
    // Creates / advances the bond of this pair. Returns true and fills `out`
    // if the bond is intact after the step.
    bool advance(SurfacesCloseData &d, GbBondOutput &out);
    bool advancePair(SurfacesCloseData &d, const GbBondModel *model, double *state, bool update,
                     GbBondOutput &out);
    bool advanceWall(SurfacesCloseData &d, const GbBondModel *model, double *state, bool update,
                     GbBondOutput &out);
    void apply(const GbBondOutput &out, ForceData &i_forces, ForceData &j_forces);
    void failed(const SurfacesCloseData &d, const char *call);

    BondNonlinearParameters parameters_;
    const bool isWall_;
    const size_t stateLen_;
    int offset_;
};

}
}

#endif
