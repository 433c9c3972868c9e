// The engine-facing half of `cohesion bond/nonlinear`: history slots, and per
// pair (or particle-wall contact) one call into the core, whose forces and
// torques replace the contact model's while the bond is intact
// (docs/models/bond-nonlinear.md, "Creation"). No physics here: see rust-core.
//
// Compiled once (bond_nonlinear_cohesion.cpp); the CohesionModel<> template
// specialisation in cohesion_model_bond_nonlinear.h only inherits from it.
// The pair callbacks' common case is inline here, so that the engine's pair
// loop, compiled with each model combination, settles it without a call.
#ifndef GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H
#define GRANBOND_LIGGGHTS_BOND_NONLINEAR_COHESION_H

#include "bond_nonlinear_parameters.h"
#include "bond_book.h"
#include "bond_index.h"
#include "run_checks.h"

#include <unordered_set>
#include <vector>

namespace LAMMPS_NS {
class PairGran;
}

namespace granbond {
class FixGranbondAtoms;
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
    // number of atoms changed (insertion), a point every rank reaches; and,
    // in a force pass, the sweep of the index of pair bonds (bond_index.h)
    // before the engine's pair loop; endPass sweeps the bonds that formed
    // in the loop.
    void beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &);
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &);

    // Overlapping spheres: the bond acts in endSurfacesIntersect, after the
    // normal, tangential and rolling models have added their forces. An
    // intact bond the pass swept, its loads already at the atoms, only
    // replaces those forces by nothing and keeps its record. A model that
    // keeps the contact's tangential and rolling loads under the bond (the
    // core's granbond_bond_keeps_contact_tangential) acts here instead,
    // between the normal model and the tangential one, and so replaces the
    // normal load alone.
    void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (keepsTangential(sidata)) bondOverlapping(sidata, i_forces, j_forces);
    }
    void endSurfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (!keepsTangential(sidata)) bondOverlapping(sidata, i_forces, j_forces);
    }
    void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
    {
        if (!sweptAtAtoms(scdata)) close(scdata, i_forces, j_forces);
    }

    // What per-bond output reads (bond_local.cpp): the pair style, where
    // the bond record (granbond_record_layout without the contact) lies in
    // a pair's history, the status slot in it, and each type pair's model.
    LAMMPS_NS::PairGran *pairStyle() const { return pair_; }
    int recordOffset() const { return offset_; }
    size_t statusSlot() const { return status_; }
    const GbBondModel *model(int itype, int jtype) const { return parameters_.model(itype, jtype); }
    // The bonds' states stepped in rows, and the loads of the latest force
    // pass, written back to the pairs' records (bond_index.h), for what
    // reads or moves them after the pass: the engine's re-neighbouring, a
    // run's end, a restart file, per-bond and per-contact output. True if
    // it wrote rows back.
    bool writeBack();

private:
    // Where a bond that formed in the pair loop lies in the index.
    struct Formed {
        size_t index, at;   // index_[index], bond `at`
    };

    // Creates the bond of this pair and advances it at once (or advances a
    // wall bond). Returns true and fills `out` if the bond is intact after
    // the step: then its loads replace the contact models'.
    bool advance(SurfacesCloseData &d, GbBondOutput &out);
    void pairKinematics(const SurfacesCloseData &d, GbPairKinematics &k) const;
    void createPair(const SurfacesCloseData &d, const GbBondModel *model, const GbPairKinematics &k,
                    double *state, bool &created);
    // A pair of an intact bond whose loads this pass's sweep added to the
    // atoms: its flag set to keep the record.
    bool sweptAtAtoms(SurfacesCloseData &d)
    {
        if (!direct_) return false;
        if (d.i != lastAtom_) atomReached(d.i);
        if (!d.contact_history || d.contact_history[statusAt_] != GB_BOND_STATUS_INTACT) return false;
        if (d.contact_flags) *d.contact_flags |= LIGGGHTS::ContactModels::CONTACT_COHESION_MODEL;
        return true;
    }
    void bondOverlapping(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (!sweptAtAtoms(sidata)) {
            intersecting(sidata, i_forces, j_forces);
            return;
        }
        i_forces.reset();
        j_forces.reset();
    }
    bool keepsTangential(const SurfacesIntersectData &d) const
    {
        return keepsTangential_ && keepsTangentialFor(d.itype, d.jtype);
    }
    bool keepsTangentialFor(int itype, int jtype) const;
    void intersecting(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    void close(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces);
    bool swept(SurfacesCloseData &d);
    bool unbondable(SurfacesCloseData &d);
    void atomReached(int i);
    Formed form(SurfacesCloseData &d, const GbBondModel *model);
    bool sweepNow(const Formed &f, GbBondOutput &out);
    void applyKept(SurfacesCloseData &d, ForceData &i_forces, ForceData &j_forces);
    void indexBonds();
    BondIndex &indexFor(const GbBondModel *model);
    void keepLoadsIfRead(BondIndex &b) const;
    void sweepIndex();
    void sweepAhead(int upto);
    void sweepRange(BondIndex &b, size_t first, size_t last, GbSweepTally &t);
    void settleBroken(BondIndex &b, size_t from);
    void checkIndex();
    struct AtomSums {
        double *f, *torque;   // atom->f[0], atom->torque[0]
        int nlocal, newton;
        bool virial;          // the pair style's evflag
    };
    void addToAtoms(const AtomSums &sums, int i, int j, const GbBondOutput &out);
    // The loads of a setup pass where the model computes them afresh
    // (granbond_bond_setup_compute); false: apply the kept ones.
    bool setupAfresh(SurfacesCloseData &d, const GbBondModel *model, double *state, GbBondOutput &out);
    bool advanceWall(SurfacesCloseData &d, const GbBondModel *model, double *state, GbBondOutput &out,
                     bool &created);
    void apply(const GbBondOutput &out, ForceData &i_forces, ForceData &j_forces);
    void failed(int i, int j, const char *call);
    // Bookkeeping of one step of a bond (update passes): counters, break log.
    // `wallDelta`: for wall bonds, the vector from the wall point to the centre.
    void account(const GbBondModel *model, int i, int j, const double *wallDelta, const double *state,
                 bool created, const GbBondOutput &out);
    bool countsHere(int i, int j) const;
    // The core's checks of the time step (warned at a run's start, and when
    // the atom count changes if the limit moved) and, at a run's start, of
    // the creation rules (each finding once).
    void runChecks(bool runStart);
    void sayLaw(const char *style);
    // Counts the bonds that vanished with their atoms (pair bonds; see the
    // definition); collective, at the end of a pass.
    void countVanished();
    void checkRenumbering();
    void forgetRecordsOfNewborn();

    BondNonlinearParameters parameters_;
    bool keepsTangential_;      // some type pair's model keeps the contact's tangential loads
    const bool isWall_;
    const size_t stateLen_;
    int offset_;        // core state slots
    int outputOffset_;  // last output (GB_STATE_KIND_BOND_OUTPUT slots)
    size_t status_;     // the status slot in the state (the core's table)
    size_t statusAt_;   // ... in the pair's history: offset_ + status_
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
    bool lossCheck_;            // count vanished bonds at the end of this pass
    bool warnedLost_;
    BondBalance balance_;

    LAMMPS_NS::PairGran *pair_;   // null for walls
    bool sweeping_;               // a force pass of pairs: the index is swept (sweepIndex)
    bool direct_;                 // ... and the bonds' loads go straight to the atoms
    bool createsNow_;             // a bond may form in this pass (force passes only)
    int cursor_;                  // position of the latest atom in the neighbour list (atomReached)
    int lastAtom_;
    std::vector<BondIndex> index_;   // per bond model: the intact pair bonds (bond_index.h)
    std::vector<size_t> sweptTo_;    // per index: the bonds before it are swept in this pass
    std::vector<size_t> sweepEnd_;   // per index: its size at the pass's start (later ones formed in it)
    int aheadTo_;                    // the atoms of the list up to this position have their bonds swept
    // Atoms whose bonds are swept ahead of the loop at a time: their
    // records stay in cache until the loop reads them.
    static const int kSweepAheadAtoms = 128;
    bigint indexedAt_;               // neighbor->ncalls when index_ was built; -1: to be built
    bool rows_;                      // index_ steps the bonds' states in rows (indexFor)
    std::unordered_set<const double *> brokeNow_;   // records of the bonds this pass's sweep broke
    bool pruneIndex_;                // a bond formed and broke at once in the loop: drop it at the pass's end
    bool checkIndex_;                // GRANBOND_CHECK_INDEX: recount the index after each pass
};

}
}

#endif
