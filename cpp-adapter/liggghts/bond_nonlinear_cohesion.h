// The engine-facing half of `cohesion bond/nonlinear`: per pair (or
// particle-wall contact), whose forces and torques the bond replaces while
// it is intact (docs/models/bond-nonlinear.md, "Creation"). No physics here:
// see rust-core.
//
// Pair bonds live in the core's bond store (fix granbond/bonds,
// bonds_fix.h; docs/development.md, "Where a bond lives"): each force pass
// links it after a list build, steps every bond at beginPass and adds the
// loads to the atoms; the pair loop's callbacks only replace a bonded
// pair's contact loads (a bit of the pair's contact flag caches the store)
// and propose pairs for bonds at a creation step; endPass steps the bonds
// formed in the loop. Wall bonds live in their spheres' store (fix
// granbond/wallbonds, wall_bonds_fix.h; bond_nonlinear_walls.cpp).
//
// Compiled once (bond_nonlinear_cohesion.cpp); the CohesionModel<> template
// specialisation in cohesion_model_bond_nonlinear.h only inherits from it.
// The pair callbacks' common case is inline here, so that the engine's pair
// loop, compiled with each model combination, settles it without a call.
#ifndef GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H
#define GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H

#include "bond_nonlinear_parameters.h"
#include "bond_book.h"
#include "run_checks.h"

#include <string>
#include <vector>

// The pair callbacks are inline in the engine's loop whatever the
// compiler's estimate of their size.
#if defined(__GNUC__)
#define GRANBOND_INLINE inline __attribute__((always_inline))
#else
#define GRANBOND_INLINE inline
#endif

namespace LAMMPS_NS {
class PairGran;
class FixWallGran;
}

namespace granbond {
class FixGranbondAtoms;
class BondStoreFix;
namespace liggghts {
class WallBondsFix;

using LIGGGHTS::ContactModels::ForceData;
using LIGGGHTS::ContactModels::SurfacesCloseData;
using LIGGGHTS::ContactModels::SurfacesIntersectData;

// The bit of a pair's contact flag that caches "bonded" (the engine's
// models use bits 0-4 and 31); voigt_contact reads it under this name.
static const int kBondedFlag = 1 << 5;
inline const char *bondedFlagName() { return "bondnonlinear_bonded_flag"; }

class BondNonlinearCohesion : public LIGGGHTS::ContactModels::CohesionModelBase {
public:
    BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                          LIGGGHTS::ContactModels::ContactModelBase *cmb);
    ~BondNonlinearCohesion();

    void registerSettings(::Settings &settings) { parameters_.registerSettings(settings); }
    // Once the deck is read (and before the contact models connect), tells
    // the voigt sub-models of the style what the contact does under the
    // bond: the switch, or where the deck does not give it, the law's.
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *cmb);
    void connectToProperties(::PropertyRegistry &registry);
    // Pairs only (walls have no pass hooks): the time-step check when the
    // number of atoms changed (insertion), a point every rank reaches; in
    // a force or setup pass, the store's bonds linked, stepped and their
    // loads added to the atoms; endPass steps the bonds formed in the loop.
    void beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &);
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &);

    // Overlapping spheres: the bond acts in endSurfacesIntersect, after the
    // normal, tangential and rolling models have added their forces, and
    // replaces them by nothing (its loads are at the atoms). A model that
    // keeps the contact's tangential and rolling loads under the bond (the
    // core's granbond_bond_keeps_contact_tangential) acts here instead,
    // between the normal model and the tangential one, and so replaces the
    // normal load alone.
    //
    // The engine's loop calls these for every listed pair, so they are kept
    // inline (the compiler would call them otherwise): in the common case,
    // pairs of a pass in which no bond forms (`plain_`), a bonded pair's
    // loads are cleared and the rest is left alone, and spheres apart are
    // not touched at all.
    GRANBOND_INLINE void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (keepsTangential(sidata)) overlapping(sidata, i_forces, j_forces);
    }
    GRANBOND_INLINE void endSurfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                              ForceData &j_forces)
    {
        if (plain_) {
            if (sidata.rsq == 0.0) coincident(sidata);
            if (bondedFlag(sidata)) {
                i_forces.reset();
                j_forces.reset();
            }
            return;
        }
        if (!keepsTangential(sidata)) overlapping(sidata, i_forces, j_forces);
    }
    GRANBOND_INLINE void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
    {
        if (!closeActs_) return;
        if (isWall_) {
            close(scdata, i_forces, j_forces);
            return;
        }
        if (!bondedFlag(scdata)) pairBonds(scdata);
    }

    // What per-bond output reads (bond_local.cpp): the store and each type
    // pair's model; each bond's output of the latest force pass, in store
    // order, kept while `bondOutputUsers` is non-zero; whether the store
    // holds the present atoms' bonds (its latest pass is of this step).
    const GbBondModel *model(int itype, int jtype) const { return parameters_.model(itype, jtype); }
    GbBondStore *bondStore() const;
    bool storeCurrent() const;
    const std::vector<GbBondOutput> &bondOutputs() const { return outputs_; }
    int bondOutputUsers = 0;
    // The energy budget of this rank's pair bonds (compute granbond/energy,
    // while `energyUsers` is non-zero; kept from the next run's start):
    // stored now, dissipated by damping and by hysteresis, released by
    // breaks (J). Wall bonds keep none.
    static const int kEnergyTerms = 4;
    void energyTerms(double out[kEnergyTerms]) const;
    int energyUsers = 0;
    // Bond `k`'s energies in the store's order (stored, dissipated by damping
    // and by hysteresis: granbond_bond_energy_field_info), kept while
    // `energyOutputUsers` (compute pair/gran/local/bond asking for them) is
    // non-zero; kept from the next run's start.
    void bondEnergy(size_t k, double *out) const;
    int energyOutputUsers = 0;
    // computeDissipatedEnergy on (LIGGGHTS-INL's switch; the engine's
    // surface model then holds the per-atom `dissipated_energy`): after
    // each force pass every atom's row gets minus the damping loads its
    // bonds put on it, in columns 2-7, as INL's linear bond files them
    // (granbond_bond_store_add_dissipated_shares).
    void addDissipatedShares();

    // Walls: the counts taken from the store, relinked if atoms moved since
    // (before the counts are read); and the bonds lost since the last
    // warning told, with their causes, once (collective).
    void refreshWall();
    void warnWallLosses();
    void checkWallStore();   // GRANBOND_CHECK_STORE (collective)

    // Pairs: the contact distance factor of a force pass in which no bond
    // can form lowered to what the rest of the deck registered (from fix
    // granbond/reach's pre_force), and put back (at the pair loop's end,
    // and in its post_force) before anything else reads it
    // (contact_reach.cpp).
    void narrowReach();
    void widenReach();

private:
    static bool bondedFlag(const SurfacesCloseData &d) { return d.contact_flags && (*d.contact_flags & kBondedFlag); }
    void overlapping(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (isWall_) {
            intersecting(sidata, i_forces, j_forces);
            return;
        }
        if (sidata.rsq == 0.0) coincident(sidata);
        if ((bondedFlag(sidata) || (mayForm_ && pairBonds(sidata))) && !keepsContactLoads(sidata.itype, sidata.jtype)) {
            if (keepsTangential(sidata)) {
                keepUnderBond(sidata, i_forces, j_forces);
                return;
            }
            i_forces.reset();
            j_forces.reset();
        }
    }
    // Leaves of the loads added so far those the core keeps under the bond
    // (granbond_bond_contact_loads_under_bond): a normal model's load goes,
    // and so does only the normal part of a whole voigt contact's.
    void keepUnderBond(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    // Whether the bond of the type pair leaves the contact's loads on
    // overlapping spheres and adds its own (the core's
    // granbond_bond_keeps_contact_loads: LIGGGHTS-INL's linear bond).
    bool keepsContactLoads(int itype, int jtype) const
    {
        if (!keepsLoads_) return false;
        const GbBondModel *m = parameters_.model(itype, jtype);
        return m && granbond_bond_keeps_contact_loads(m) != 0;
    }
    bool keepsTangential(const SurfacesIntersectData &d) const
    {
        return keepsTangential_ && keepsTangentialFor(d.itype, d.jtype);
    }
    bool keepsTangentialFor(int itype, int jtype) const;

    // ---- pair bonds, in the store (bond_nonlinear_pairs.cpp)
    // A pair the loop proposes at a creation step (or a `bonded yes`
    // clump's): bonded here, or by the rank that owns it; returns whether
    // it is a bond from now on (its flag set).
    bool pairBonds(SurfacesCloseData &d);
    // Ends the run: the pair has no axis, nor have the contact models.
    void coincident(const SurfacesCloseData &d);
    void linkBonds();
    void markBonded();
    void stepBonds(bool advance);
    void takeBroken(bool advance);
    void finishPairPass();
    void countPairs();
    void checkStore();
    void failPair(int i, int j, const char *what);

    // ---- wall bonds, in their spheres' store (bond_nonlinear_walls.cpp)
    void connectWall();
    void linkWall();
    void syncWallTally();
    uint32_t wallNumber(const SurfacesCloseData &d) const;
    int visitWall(SurfacesCloseData &d, GbBondOutput &out);
    void apply(const GbBondOutput &out, ForceData &i_forces);
    void intersecting(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    void close(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces);
    void failed(int i, int j, const char *call);
    // A broken wall bond in the break log. `wallDelta`: the vector from the
    // wall point to the centre.
    void account(const GbBondModel *model, int i, const double *wallDelta, const GbBondOutput &out);

    // The core's checks of the time step (warned at a run's start, and when
    // the atom count changes if the limit moved) and, at a run's start, of
    // the creation rules (each finding once).
    void runChecks(bool runStart);
    // The factor before this model registered its reach, at connect.
    void noteReach(double before);
    void sayLaw(const char *style);
    void checkRenumbering();
    void forgetRecordsOfNewborn();

    BondNonlinearParameters parameters_;
    bool keepsTangential_;      // some type pair's model keeps the contact's tangential loads
    bool keepsLoads_ = false;   // ... keeps all the contact's loads (keepsContactLoads)
    const bool isWall_;
    int offset_;        // walls: the contact's flag (the bond's status as the store said)
    BondTally tally_;
    BondBook *book_;    // this instance's book (looked up once: std::map)
    // `fix particletemplate/multiplespheres ... bonded yes` (null if none)
    LAMMPS_NS::FixPropertyAtom *clumpIds_;
    // which atoms bonds have seen, under which IDs (fix_granbond_atoms.h)
    FixGranbondAtoms *atoms_;
    bigint checkedNatoms_;
    bigint firstStep_;          // where this model's first run started
    TimestepWarning timestepWarning_;
    SaidOnce said_;
    bool saidLaw_;              // the law's line is printed (sayLaw)

    LAMMPS_NS::PairGran *pair_;   // null for walls
    BondStoreFix *bonds_;         // pairs: the bonds' home
    std::vector<int32_t> kinds_;  // per (itype, jtype): the bond kind (its model's place in the table), -1 none
    std::vector<char> createsNow_;   // per kind, this pass
    bool passing_;                // a force or setup pass of pairs is under way
    bool advance_;                // ... a force pass
    bool mayForm_;                // ... in which a bond may form
    // Set with mayForm_ (setMayForm): the pair callbacks' common case, a
    // pair of a pass in which no bond forms, of a model that replaces all
    // the contact's loads (`plain_`); whether surfacesClose has anything to
    // do (`closeActs_`: walls, or a bond may form).
    bool plain_ = false;
    bool closeActs_ = true;
    void setMayForm(bool mayForm)
    {
        mayForm_ = mayForm;
        plain_ = !isWall_ && !keepsTangential_ && !keepsLoads_ && !mayForm_;
        closeActs_ = isWall_ || mayForm_;
    }
    bool formedThisPass_;         // bonds formed here in this pass
    bigint linkedAt_;             // neighbor->ncalls at the latest link
    double *ghostLoads_;          // this pass's loads on ghost atoms (newton off)
    std::vector<GbBondOutput> outputs_;   // per bond, the latest force pass (bondOutputUsers)
    bigint passStep_;             // step and atom count (local + ghost) of the latest pass
    bigint passAtoms_;
    bool checkStore_;             // GRANBOND_CHECK_STORE: recount the bonds after each pass
    bool warnedLost_;             // bonds lost without breaking were told (once)
    LAMMPS_NS::FixPropertyAtom *dissipated_ = nullptr;   // computeDissipatedEnergy's per-atom table, or null
    std::vector<double> shares_;  // this pass's shares, local then ghost atoms (6 doubles an atom)
    std::vector<double> relax_;   // each atom's relaxation factor, where one differs from 1 (local then ghost)

    // walls (bond_nonlinear_walls.cpp)
    LAMMPS_NS::FixWallGran *wallFix_;   // the wall fix this model belongs to
    WallBondsFix *wallBonds_;           // its bonds' home
    bigint wallLinkedAt_;               // neighbor->ncalls at the latest link of its store
    int64_t wallPass_;                  // the latest force or setup pass visited
    GbStoreCounts wallLostTold_;        // the losses told so far (warnWallLosses)
    std::vector<double> wallRestart_;   // its store's rows in a restart file read (restartRows)
    std::vector<std::string> wallRestartMeshes_;   // the meshes that numbered their walls (restartMeshes)
    std::vector<char> atomsRestart_;    // fix granbond/atoms's state there (atomsRestartState)

    // the contact distance factor (contact_reach.cpp)
    double baseReach_ = -1.0;        // what the rest of the deck registered
    double registeredReach_ = -1.0;  // the factor once this model registered its reach
    double fullReach_ = 0.0;         // the factor put back after a lowered pass
    bool narrowed_ = false;          // the factor is lowered for this pass
};

}
}

#endif
