// What the voigt sub-models of one pair style or wall fix share
// (VoigtContactShare): the deck's values, row by row of the core's Voigt
// table (the per-type-pair properties by each row's LIGGGHTS name, the
// switches), the parameters of the whole contact built from them, the
// contact frame and where the history and a bond are. Compiled in
// voigt_deck.cpp.
#ifndef GRANBOND_LIGGGHTS_VOIGT_DECK_H
#define GRANBOND_LIGGGHTS_VOIGT_DECK_H

#include "liggghts_engine.h"
#include "granbond.h"

#include <deque>
#include <vector>

namespace granbond {
namespace liggghts {

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

class VoigtContactShare {
public:
    // Joins the share of ContactModel `owner`; `*first` tells whether the
    // caller is the first voigt sub-model constructed for it.
    static VoigtContactShare *attach(const void *owner, bool *first);
    static void detach(const void *owner);

    // The switches of the parts in `owns` under their LIGGGHTS names, and
    // once the bond table's switch of what the contact does under a bond
    // (granbond_bond_parameter_sets_creation 2): a cohesion model of the
    // style registers it too, the engine sets both from the one word, and
    // that model has the last word once the deck is read (bondSays).
    void registerSettings(::Settings &settings, unsigned owns);
    // Connects the per-type-pair properties of the parts in `reads`.
    void connect(::PropertyRegistry &registry, const char *caller, unsigned reads);
    // The deck's rows of the parts in `parts` for every pair of types
    // 1..ntypes, over the core's defaults; the switches that say a part is
    // present (LiggghtsSource FIXED) on for the parts in `present`. The core
    // refuses a value out of range, the message naming `caller`.
    std::vector<GbVoigtParams> params(LAMMPS_NS::Error *error, const char *caller, int ntypes, unsigned parts,
                                      unsigned present) const;
    // Writes the rows of `parts` into the whole contact's parameters, and
    // rebuilds its models when they are used.
    void contribute(LAMMPS_NS::Error *error, const char *caller, int ntypes, unsigned parts);
    // The whole contact's parameters of a type pair (what a voigt normal
    // model hands on to stock models: it reads the tangential part too).
    const GbVoigtParams &whole(int itype, int jtype) const { return params_[itype * stride_ + jtype]; }

    // The whole contact in one core call: normal and tangential voigt, with
    // the rolling history right after the tangential one when rolling is
    // voigt too (the engine gives consecutive offsets to consecutive
    // sub-models, and only cohesion registers between normal and tangential).
    bool fused() const { return normal && tangential_offset >= 0; }
    bool fusedRolling() const { return fused() && rolling_offset == tangential_offset + 3; }
    const GbVoigtModel *fusedModel(int itype, int jtype) const { return table_.at(itype, jtype); }
    const VoigtModelTable &fusedTable() const { return table_; }

    // What the contact does under a bond of the style of ContactModel
    // `owner`, as its bond model says once the deck is read: the switch, or
    // the law's where the deck does not give it. Nothing without a voigt
    // sub-model.
    static void bondSays(const void *owner, bool goesOnUnderBond);
    // Finds where a `cohesion bond/nonlinear` of the same style says a bond
    // is, if there is one (all sub-models are constructed by then): a bit of
    // a pair's contact flag, or a wall bond's status slot.
    void findBond(LIGGGHTS::ContactModels::ContactModelBase *cmb);
    // With that switch off, an intact bond holds the contact's history at
    // zero: the contact starts afresh when the bond breaks.
    bool heldByBond(const LIGGGHTS::ContactModels::SurfacesCloseData &d) const
    {
        if (!bondMayHold()) return false;
        if (bondedFlag_ > 0) return d.contact_flags && (*d.contact_flags & bondedFlag_);
        // the wall bond's rest length: positive while intact
        return d.contact_history && d.contact_history[bondStatus_] > 0.0;
    }
    // Known once the settings are read and every sub-model is constructed.
    bool bondMayHold() const { return (bondStatus_ >= 0 || bondedFlag_ > 0) && !goesOnUnderBond_; }

    GbContactFrame frame;
    bool normal;               // model voigt present
    int tangential_offset;     // history offset of tangential voigt, -1 if absent
    int rolling_offset;        // history offset of rolling_friction voigt, -1 if absent

private:
    VoigtContactShare();
    void fill(LAMMPS_NS::Error *error, const char *caller, GbVoigtParams &p, int a, int b, unsigned parts) const;

    int users_;
    int stride_;
    bool settingRegistered_;
    bool goesOnUnderBond_;
    int bondStatus_;   // history offset of a wall bond's status, -1 without one
    int bondedFlag_;   // the contact flag's bit of a pair bond, -1 without one
    std::vector<double **> values_;   // per row: the connected property, or null
    std::deque<bool> switches_;       // per row: the engine's Settings take a bool&
    std::vector<GbVoigtParams> params_;
    VoigtModelTable table_;
};

}
}

#endif
