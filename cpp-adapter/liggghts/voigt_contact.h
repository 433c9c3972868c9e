// The engine-facing half of the Voigt contact (docs/models/voigt.md) as
// three LIGGGHTS sub-models, `model voigt`, `tangential voigt` and
// `rolling_friction voigt`, each usable with stock models in the other
// slots. No physics here: see rust-core (src/contact).
//
// One class, VoigtSubModel, is all three (voigt_contact.cpp, compiled
// once); the NormalModel<> / TangentialModel<> / RollingModel<>
// specialisations in voigt_models.h only name the part each one is.
//
// The sub-models of one ContactModel (one pair style or one wall fix) share a
// VoigtContactShare (voigt_deck.h): the deck's values, the contact frame of
// the contact at hand (computed by the first voigt sub-model the engine
// calls, read by the later ones) and, when normal and tangential are both
// voigt, one core model per type pair with all their parameters, so `model
// voigt` advances the whole contact in a single core call and the other two
// add nothing.
#ifndef GRANBOND_LIGGGHTS_VOIGT_CONTACT_H
#define GRANBOND_LIGGGHTS_VOIGT_CONTACT_H

#include "liggghts_engine.h"
#include "contact_interface.h"
#include "pointers.h"
#include "granbond.h"
#include "run_checks.h"
#include "voigt_deck.h"

#include <cstddef>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace granbond {
namespace liggghts {

using LIGGGHTS::ContactModels::ForceData;
using LIGGGHTS::ContactModels::SurfacesCloseData;
using LIGGGHTS::ContactModels::SurfacesIntersectData;

// Records handed between the engine, this adapter and the core (the
// engine's contact data, the frame, the core's output, the engine's force
// accumulators) are written just before they are read, and the stores are
// still in flight. A load that spans two stores cannot be served from the
// store buffer (store-to-load forwarding fails; it waits until the stores
// reach the cache), and compilers pair neighbouring doubles into 16-byte
// loads at will (the engine resets ForceData in 16-byte stores at offsets
// 0, 16, 32: a paired load of delta_torque[0..1] at 24 spans two of them).
// So this code reads such records one double at a time, as the core reads
// the frame: each load is served by the store that wrote it, whatever
// widths either compiler chose; only where both layouts are known does it
// read pairs (addPairLoads).
inline double fresh(const double &x) { return *static_cast<const volatile double *>(&x); }
inline void addTo(double &x, double d)
{
    volatile double &v = x;
    v = v + d;
}
inline void subtractFrom(double &x, double d)
{
    volatile double &v = x;
    v = v - d;
}

// The loads of a pair added to the engine's accumulators of i and j, a
// double at a time.
inline void addScalarPairLoads(ForceData &i_forces, ForceData &j_forces, const double *force_i,
                               const double *torque_i, const double *torque_j)
{
    for (int k = 0; k < 3; k++) {
        const double f = fresh(force_i[k]);
        addTo(i_forces.delta_F[k], f);
        subtractFrom(j_forces.delta_F[k], f);
        addTo(i_forces.delta_torque[k], fresh(torque_i[k]));
        addTo(j_forces.delta_torque[k], fresh(torque_j[k]));
    }
}

// The same in 16-byte pairs of doubles: ForceData is delta_F and
// delta_torque side by side, reset by the engine in 16-byte stores at
// offsets 0, 16 and 32, and the core's output is force_i, torque_i and
// torque_j side by side, written so that each pair read below (offsets 0,
// 16, 32 and 56) lies within one of its stores. Each load is
// then served by one store, and each lane is the scalar operation of
// addScalarPairLoads: delta_F[2] - force_i[2] as delta_F[2] + (-force_i[2]), the same
// IEEE operation.
inline void addPairLoads(ForceData &i_forces, ForceData &j_forces, const GbContactOutput &out)
{
#if defined(__SSE2__)
    static_assert(offsetof(ForceData, delta_torque) == 3 * sizeof(double), "ForceData: delta_F, delta_torque");
    static_assert(offsetof(GbContactOutput, torque_i) == 3 * sizeof(double) &&
                      offsetof(GbContactOutput, torque_j) == 6 * sizeof(double),
                  "GbContactOutput: force_i, torque_i, torque_j");
    const double *const o = out.force_i;
    double *const fi = i_forces.delta_F, *const fj = j_forces.delta_F;
    for (int k = 0; k < 6; k += 2) _mm_storeu_pd(fi + k, _mm_add_pd(_mm_loadu_pd(fi + k), _mm_loadu_pd(o + k)));
    _mm_storeu_pd(fj, _mm_sub_pd(_mm_loadu_pd(fj), _mm_loadu_pd(o)));
    _mm_storeu_pd(fj + 2, _mm_add_pd(_mm_loadu_pd(fj + 2), _mm_set_pd(o[6], -o[2])));
    _mm_storeu_pd(fj + 4, _mm_add_pd(_mm_loadu_pd(fj + 4), _mm_loadu_pd(o + 7)));
#else
    addScalarPairLoads(i_forces, j_forces, out.force_i, out.torque_i, out.torque_j);
#endif
}

// Ends the run on this rank with the core's message.
void voigtFailed(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &d, const char *who);

// A voigt sub-model: the part of the Voigt contact it computes
// (GB_CONTACT_PART_*), with what the engine asks of a normal, tangential
// or rolling model. Tangential and rolling keep three slots of the core's
// contact state each (forgotten when the contact ends).
class VoigtSubModel : protected LAMMPS_NS::Pointers {
public:
    VoigtSubModel(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                  LIGGGHTS::ContactModels::ContactModelBase *cmb, GbContactPart part);
    ~VoigtSubModel();

    void registerSettings(::Settings &settings) { share_->registerSettings(settings, partBit(part_)); }
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *cmb)
    {
        share_->findBond(cmb);
    }
    void connectToProperties(::PropertyRegistry &registry);
    // The engine's surfacesIntersect of part `Part`: its bit of the contact
    // flag and the part, or in voigt x voigt the whole contact from the
    // normal model and nothing from the others. Always inline, flag and
    // part constants: the engine's wall loop would call it, and in voigt x
    // voigt the tangential and rolling models then cost only the flag and
    // the test.
    template<GbContactPart Part>
    inline __attribute__((always_inline)) void intersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                         ForceData &j_forces)
    {
        if (sidata.contact_flags)
            *sidata.contact_flags |= Part == GB_CONTACT_PART_NORMAL       ? LIGGGHTS::ContactModels::CONTACT_NORMAL_MODEL
                                   : Part == GB_CONTACT_PART_TANGENTIAL ? LIGGGHTS::ContactModels::CONTACT_TANGENTIAL_MODEL
                                                                          : LIGGGHTS::ContactModels::CONTACT_ROLLING_MODEL;
        if (Part == GB_CONTACT_PART_NORMAL && whole_)
            wholeContact(sidata, i_forces, j_forces);
        else if (!skip_)
            partOnly(sidata, i_forces, j_forces);
    }
    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &);
    // Only the pair style calls it, once before each pass over its contacts,
    // with the pass's computeflag and shearupdate already set.
    void beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &)
    {
        if (part_ != GB_CONTACT_PART_NORMAL || wall_) return;
        passInPlace_ = pairInPlace_ && sidata.computeflag && sidata.shearupdate;
        if (checkPending_ || atom->natoms != checkedNatoms_) checkTimestep();
        // later sub-models rebuild the fused table when they connect, and a
        // run may change dt: both are fixed for the pass
        pairModels_ = share_->fusedTable().data();
        pairStride_ = share_->fusedTable().ntypes() + 1;
        pairDt_ = update->dt;
    }
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) { passInPlace_ = false; }

    // The pair style's current pass is a force pass and the whole contact's
    // state is stored in place (rolling voigt too, no bond that may hold
    // the contact): stepInPlace takes each of its pairs, and the tangential
    // and rolling models add nothing. Always false for a wall.
    bool passInPlace() const { return passInPlace_; }
    // wholeContact's common case for a pair, inline in the engine's pair
    // loop: the one core call on the engine's data and the stored state,
    // the loads added in pairs.
    void stepInPlace(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        GbContactOutput out;
        if (granbond_voigt_compute_normal_unchecked(pairModels_[sidata.itype * pairStride_ + sidata.jtype], sidata.en,
                                                    sidata.r, sidata.radi, sidata.radj, sidata.v_i, sidata.v_j,
                                                    sidata.omega_i, sidata.omega_j, pairDt_,
                                                    &sidata.contact_history[pairState_], &out) != GB_STATUS_OK)
            voigtFailed(lmp, sidata, sub_.words);
        sidata.Fn = fresh(out.normal_force);
        addPairLoads(i_forces, j_forces, out);
    }

private:
    // The core's time-step check of the whole contact (the combined model
    // when tangential, and rolling, are voigt too; else the normal part
    // with the tangential spring it hands on):
    // warned at a run's first pass, and when the atom count changes if the
    // limit moved. At the first pass, not when connected: the other voigt
    // sub-models connect after this one. Pair contacts only (wall_: this
    // instance serves a wall).
    void checkTimestep();
    // The part alone, on the frame: the normal force, or the tangential or
    // rolling step on the contact's slots.
    void partOnly(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    // The slots a step or an evaluation reads, of the `len` the core
    // writes from `stored` on, `own` of them this model's: the stored ones
    // in a real force step, else a copy in `scratch` (setup pass,
    // per-contact output; the slots not ours zero), to be written back
    // after a force step (`*writeBack`) when not all are ours; under a bond
    // that holds the contact (heldByBond), zeroed stored slots and a zero
    // `scratch`.
    double *slots(const SurfacesIntersectData &sidata, double *stored, int own, int len, double *scratch,
                  bool *writeBack);
    // Fills share_->frame if this model computes it (`always`: also when
    // another voigt model would have), and returns the part's three slots.
    double *begin(const SurfacesIntersectData &sidata, bool always, double *scratch);
    // what the stock tangential, rolling and cohesion models read: kn, kt,
    // gamman, gammat of the type pair
    void handOn(SurfacesIntersectData &sidata);
    void stepFused(SurfacesIntersectData &sidata, double *state, GbContactOutput &out);
    // normal + tangential (+ rolling) voigt in one core call
    void wholeContact(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    // the cases wholeContact leaves aside: without rolling voigt, setup and
    // output passes, a contact held by a bond
    __attribute__((noinline)) void wholeContactAside(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                     ForceData &j_forces);

    const GbContactPart part_;
    const GbSubModel sub_;        // what the deck calls it and the parts it reads (the core's)
    const int contactFlag_;       // its bit of a pair's contact flag
    const void *owner_;
    VoigtContactShare *share_;
    VoigtModelTable models_;      // the rows the part reads, over the core's defaults
    bool computesFrame_;          // the first voigt sub-model constructed
    bool whole_, skip_;           // model voigt does the whole contact, and the others nothing
    bool fusedRolling_;           // share_->fusedRolling(), known once connected
    int offset_;                  // history offset of the part's slots (tangential, rolling)
    bool pairInPlace_;            // known once connected
    bool passInPlace_;            // pairInPlace_ in a force pass of the pair style
    int pairState_;               // history offset of the fused state
    // the fused table and dt as of the pair style's current pass
    const GbVoigtModel *const *pairModels_;
    int pairStride_;
    double pairDt_;
    const bool wall_;
    bool checkPending_;           // a run starts: check at its first pass
    LAMMPS_NS::bigint checkedNatoms_;
    TimestepWarning timestepWarning_;
};

}
}

#endif
