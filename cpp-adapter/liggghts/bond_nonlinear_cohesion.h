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
#include "bond_book.h"

namespace granbond {
namespace liggghts {

using LIGGGHTS::ContactModels::ForceData;
using LIGGGHTS::ContactModels::SurfacesCloseData;
using LIGGGHTS::ContactModels::SurfacesIntersectData;

class BondNonlinearCohesion : public LIGGGHTS::ContactModels::CohesionModelBase {
public:
    BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                          LIGGGHTS::ContactModels::ContactModelBase *cmb);
    ~BondNonlinearCohesion();

    void registerSettings(::Settings &settings) { parameters_.registerSettings(settings); }
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *) {}
    void connectToProperties(::PropertyRegistry &registry);
    // Pairs only (walls have no pass hooks): the time-step check when the
    // number of atoms changed (insertion), a point every rank reaches.
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &);
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
                     GbBondOutput &out, bool &created);
    bool advanceWall(SurfacesCloseData &d, const GbBondModel *model, double *state, bool update,
                     GbBondOutput &out, bool &created);
    void apply(const GbBondOutput &out, ForceData &i_forces, ForceData &j_forces);
    void failed(const SurfacesCloseData &d, const char *call);
    // Bookkeeping of one step of a bond (update passes): counters, break log.
    void account(const SurfacesCloseData &d, const double *state, bool created, const GbBondOutput &out);
    bool countsHere(const SurfacesCloseData &d) const;
    void storeOutput(double *slots, const GbBondOutput &out) const;
    void loadOutput(const double *slots, GbBondOutput &out) const;
    // Warns (rank 0) if the step exceeds the critical / recommended step of
    // the stiffest bond between the smallest and lightest spheres present.
    void checkTimestep();

    BondNonlinearParameters parameters_;
    const bool isWall_;
    const size_t stateLen_;
    int offset_;        // core state slots
    int outputOffset_;  // last output: force_i[3], T_i+T_j [3], T_i-T_j [3], sigma, tau
    BondTally tally_;
    BondBook *book_;    // this instance's book (looked up once: std::map)
    // `fix particletemplate/multiplespheres ... bonded yes` (null if none)
    LAMMPS_NS::FixPropertyAtom *clumpIds_;
    bigint checkedNatoms_;
    double warnedCritical_;
};

}
}

#endif
