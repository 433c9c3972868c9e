// The engine-facing half of the Voigt contact (docs/models/voigt.md) as
// three LIGGGHTS sub-models, `model voigt`, `tangential voigt` and
// `rolling_friction voigt`, each usable with stock models in the other
// slots. No physics here: see rust-core (src/contact).
//
// Compiled once (voigt_contact.cpp); the NormalModel<> / TangentialModel<> /
// RollingModel<> specialisations in *_model_voigt.h only inherit from these.
//
// The sub-models of one ContactModel (one pair style or one wall fix) share a
// VoigtContactShare: the contact frame of the contact at hand (computed by
// the first voigt sub-model the engine calls, read by the later ones) and,
// when normal and tangential are both voigt, one core model per type pair
// with all their parameters, so `model voigt` advances the whole contact in
// a single core call and the other two add nothing.
#ifndef GRANBOND_LIGGGHTS_VOIGT_CONTACT_H
#define GRANBOND_LIGGGHTS_VOIGT_CONTACT_H

#include "liggghts_engine.h"
#include "normal_model_base.h"
#include "tangential_model_base.h"
#include "rolling_model_base.h"
#include "granbond.h"
#include "run_checks.h"

#include <cstddef>
#include <deque>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace granbond {
namespace liggghts {

using LIGGGHTS::ContactModels::ForceData;
using LIGGGHTS::ContactModels::SurfacesCloseData;
using LIGGGHTS::ContactModels::SurfacesIntersectData;

// One validated core model per atom-type pair.
class VoigtModelTable {
public:
    VoigtModelTable() : stride_(0) {}
    ~VoigtModelTable() { clear(); }

    // params[a * (ntypes + 1) + b] for types a, b in 1..ntypes; a refusal by
    // the core ends the run with its message (which names the property).
    void build(LAMMPS_NS::Error *error, const char *who, int ntypes, const std::vector<GbVoigtParams> &params);
    const GbVoigtModel *at(int itype, int jtype) const { return models_[itype * stride_ + jtype]; }
    // As the core's checks take the table: entry a * (ntypes() + 1) + b.
    const GbVoigtModel *const *data() const { return models_.data(); }
    int ntypes() const { return stride_ - 1; }

private:
    VoigtModelTable(const VoigtModelTable &);
    VoigtModelTable &operator=(const VoigtModelTable &);
    void clear();

    int stride_;
    std::vector<GbVoigtModel *> models_;
};

// The parts of the Voigt contact (granbond_voigt_parameter_part) as bits.
inline unsigned partBit(GbContactPart part) { return 1u << static_cast<unsigned>(part); }

// What a voigt sub-model reads from the deck, row by row of the core's
// Voigt table: the per-type-pair properties of the parts it reads (by the
// row's LIGGGHTS name) and the switches of the parts it owns (registered
// with the engine's settings).
class VoigtDeck {
public:
    VoigtDeck(unsigned owns, unsigned reads);

    void registerSettings(::Settings &settings);
    void connect(::PropertyRegistry &registry, const char *caller);
    // The rows of the parts in `parts` for types a, b written into `p`; the
    // switches that say a part is present (LiggghtsSource FIXED) on for
    // the parts in `present`. The core refuses a value out of range.
    void fill(LAMMPS_NS::Error *error, const char *caller, GbVoigtParams &p, int a, int b, unsigned parts,
              unsigned present) const;
    // `fill` for every pair of types 1..ntypes, over the core's defaults.
    std::vector<GbVoigtParams> all(LAMMPS_NS::Error *error, const char *caller, int ntypes, unsigned parts,
                                   unsigned present) const;
    unsigned owns() const { return owns_; }

private:
    unsigned owns_, reads_;
    std::vector<double **> values_;   // per row: the connected property, or null
    std::deque<bool> switches_;       // per row: the engine's Settings take a bool&
};

// Writes the switches that say a part is present into `p`.
void setPresentParts(LAMMPS_NS::Error *error, const char *caller, GbVoigtParams &p, unsigned present);

class VoigtContactShare {
public:
    // Joins the share of ContactModel `owner`; `*first` tells whether the
    // caller is the first voigt sub-model constructed for it.
    static VoigtContactShare *attach(const void *owner, bool *first);
    static void detach(const void *owner);

    // Writes each type pair's parameters owned by the caller into the
    // combined set, and rebuilds the combined models when they are used.
    // Every sub-model has validated its own parameters by then.
    void contribute(LAMMPS_NS::Error *error, const char *caller, int ntypes, const VoigtDeck &deck)
    {
        resize(ntypes);
        for (int a = 1; a <= ntypes; a++)
            for (int b = 1; b <= ntypes; b++)
                deck.fill(error, caller, params_[a * stride_ + b], a, b, deck.owns(), 0);
        rebuild(error);
    }

    // The whole contact in one core call: normal and tangential voigt, with
    // the rolling history right after the tangential one when rolling is
    // voigt too (the engine gives consecutive offsets to consecutive
    // sub-models, and only cohesion registers between normal and tangential).
    bool fused() const { return normal && tangential_offset >= 0; }
    bool fusedRolling() const { return fused() && rolling_offset == tangential_offset + 3; }
    const GbVoigtModel *fusedModel(int itype, int jtype) const { return table_.at(itype, jtype); }
    const VoigtModelTable &fusedTable() const { return table_; }

    // `contactUnderBond on|off`, registered by whichever voigt sub-model
    // the engine asks for its settings first (each name once per style).
    void registerSettings(::Settings &settings);
    // Finds where a `cohesion bond/nonlinear` of the same style says a bond
    // is, if there is one (all sub-models are constructed by then): a bit of
    // a pair's contact flag, or a wall bond's status slot.
    void findBond(LIGGGHTS::ContactModels::ContactModelBase *cmb);
    // With contactUnderBond off, an intact bond holds the contact's history
    // at zero: the contact starts afresh when the bond breaks.
    bool heldByBond(const LIGGGHTS::ContactModels::SurfacesCloseData &d) const
    {
        if (!bondMayHold()) return false;
        if (bondedFlag_ > 0) return d.contact_flags && (*d.contact_flags & bondedFlag_);
        // the wall bond's rest length: positive while intact
        return d.contact_history && d.contact_history[bondStatus_] > 0.0;
    }
    // Known once the settings are read and every sub-model is constructed.
    bool bondMayHold() const { return (bondStatus_ >= 0 || bondedFlag_ > 0) && !contactUnderBond_; }

    GbContactFrame frame;
    bool normal;               // model voigt present
    int tangential_offset;     // history offset of tangential voigt, -1 if absent
    int rolling_offset;        // history offset of rolling_friction voigt, -1 if absent

private:
    VoigtContactShare();
    void resize(int ntypes);
    void rebuild(LAMMPS_NS::Error *error);

    int users_;
    int stride_;
    bool settingRegistered_;
    bool contactUnderBond_;
    int bondStatus_;   // history offset of a wall bond's status, -1 without one
    int bondedFlag_;   // the contact flag's bit of a pair bond, -1 without one
    std::vector<GbVoigtParams> params_;
    VoigtModelTable table_;
};

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

class VoigtNormal : public LIGGGHTS::ContactModels::NormalModelBase {
public:
    VoigtNormal(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                LIGGGHTS::ContactModels::ContactModelBase *cmb);
    ~VoigtNormal();

    void registerSettings(::Settings &settings);
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *cmb)
    {
        share_->findBond(cmb);
    }
    void connectToProperties(::PropertyRegistry &registry);
    double stressStrainExponent() { return 1.0; }
    // inline: voigt x voigt goes straight to the one core call
    void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (sidata.contact_flags) *sidata.contact_flags |= LIGGGHTS::ContactModels::CONTACT_NORMAL_MODEL;
        if (fused_)
            wholeContact(sidata, i_forces, j_forces);
        else
            normalPart(sidata, i_forces, j_forces);
    }
    void surfacesClose(SurfacesCloseData &, ForceData &, ForceData &) {}
    // Only the pair style calls it, once before each pass over its contacts,
    // with the pass's computeflag and shearupdate already set.
    void beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &)
    {
        if (wall_) return;
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
            voigtFailed(lmp, sidata, "model voigt");
        sidata.Fn = fresh(out.normal_force);
        addPairLoads(i_forces, j_forces, out);
    }

private:
    // The core's time-step check of the whole contact (the combined model
    // when tangential, and rolling, are voigt too; else the normal part):
    // warned at a run's first pass, and when the atom count changes if the
    // limit moved. At the first pass, not when connected: the other voigt
    // sub-models connect after this one. Pair contacts only (wall_: this
    // instance serves a wall).
    void checkTimestep();
    // what the stock tangential, rolling and cohesion models read: kn, kt,
    // gamman, gammat of the type pair
    void handOn(SurfacesIntersectData &sidata);
    void normalPart(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    void stepFused(SurfacesIntersectData &sidata, double *state, GbContactOutput &out);
    void wholeContact(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);
    // the cases wholeContact leaves aside: without rolling voigt, setup and
    // output passes, a contact held by a bond
    __attribute__((noinline)) void wholeContactAside(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                     ForceData &j_forces);

    const void *owner_;
    VoigtContactShare *share_;
    VoigtModelTable models_;
    VoigtDeck deck_;
    // per type pair, what handOn passes on: the normal and tangential parts
    std::vector<GbVoigtParams> handed_;
    int stride_;
    bool fused_, fusedRolling_;   // share_->fused(), fusedRolling(), known once connected
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

// What tangential and rolling voigt have in common: three slots of the
// core's contact state (forgotten when the contact ends), the contact frame
// they compute or read, and their own validated models. Instantiated (in
// voigt_contact.cpp) for TangentialModelBase and RollingModelBase.
template<class EngineBase>
class VoigtHistoryModel : public EngineBase {
public:
    VoigtHistoryModel(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                      LIGGGHTS::ContactModels::ContactModelBase *cmb, size_t firstSlot, const char *offsetName,
                      int contactFlag);
    ~VoigtHistoryModel();

    void registerSettings(::Settings &settings) { share_->registerSettings(settings); }
    void postSettings(LIGGGHTS::IContactHistorySetup *, LIGGGHTS::ContactModels::ContactModelBase *cmb)
    {
        share_->findBond(cmb);
    }
    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &);
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

protected:
    // Fills share_->frame if this model computes it (`always`: also when
    // another voigt model would have), and returns the three slots to
    // advance: the stored ones in a real force step, else a copy in
    // `scratch` (setup pass, per-contact output); under a bond that holds
    // the contact (heldByBond), zeroed stored slots and a zero `scratch`.
    double *begin(const SurfacesIntersectData &sidata, bool always, double *scratch);

    const void *owner_;
    VoigtContactShare *share_;
    bool computesFrame_;
    bool skip_;   // model voigt does the whole contact
    int offset_;
    const int contactFlag_;
    VoigtModelTable models_;
};

class VoigtTangential : public VoigtHistoryModel<LIGGGHTS::ContactModels::TangentialModelBase> {
public:
    VoigtTangential(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                    LIGGGHTS::ContactModels::ContactModelBase *cmb);

    void registerSettings(::Settings &settings)
    {
        deck_.registerSettings(settings);
        share_->registerSettings(settings);
    }
    void connectToProperties(::PropertyRegistry &registry);
    // inline: in voigt x voigt the call costs only the flag and the test
    void surfacesIntersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (sidata.contact_flags) *sidata.contact_flags |= LIGGGHTS::ContactModels::CONTACT_TANGENTIAL_MODEL;
        if (!skip_) intersect(sidata, i_forces, j_forces);
    }

private:
    void intersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);

    VoigtDeck deck_;
};

class VoigtRolling : public VoigtHistoryModel<LIGGGHTS::ContactModels::RollingModelBase> {
public:
    VoigtRolling(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                 LIGGGHTS::ContactModels::ContactModelBase *cmb);

    void registerSettings(::Settings &settings)
    {
        deck_.registerSettings(settings);
        share_->registerSettings(settings);
    }
    void connectToProperties(::PropertyRegistry &registry);
    void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (sidata.contact_flags) *sidata.contact_flags |= LIGGGHTS::ContactModels::CONTACT_ROLLING_MODEL;
        if (!skip_) intersect(sidata, i_forces, j_forces);
    }

private:
    void intersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces);

    VoigtDeck deck_;
};

}
}

#endif
