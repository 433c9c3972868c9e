#include "voigt_contact.h"

#include "force.h"
#include "core_bridge.h"
#include "core_message.h"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

// ------------------------------------------------------------ translation

// The engine's description of a touching contact as the core takes it:
// the engine's unit normal en (x_i - x_j over its length), the centre
// distance and the radii; for a wall (radius_j = 0) the centre's distance
// from the plane through the contact point with normal en, the wall moving
// with its velocity there. The core builds overlap, levers and R*. The
// vectors stay where the engine keeps them.
struct EngineContact {
    const double *n, *v_i, *v_j, *w_i, *w_j;
    double distance, radius_i, radius_j;
};

static const double NO_MOTION[3] = {0.0, 0.0, 0.0};

static inline EngineContact engineContact(const SurfacesIntersectData &d)
{
    EngineContact c;
    c.n = d.en;
    c.v_i = d.v_i;
    c.w_i = d.omega_i;
    c.radius_i = d.radi;
    if (d.is_wall) {
        const double *const en = d.en;
        c.distance = fresh(d.delta[0]) * fresh(en[0]) + fresh(d.delta[1]) * fresh(en[1]) +
                     fresh(d.delta[2]) * fresh(en[2]);
        c.radius_j = 0.0;
        c.v_j = d.v_j ? d.v_j : NO_MOTION;
        c.w_j = NO_MOTION;
        return c;
    }
    c.distance = d.r;
    c.radius_j = d.radj;
    c.v_j = d.v_j;
    c.w_j = d.omega_j;
    return c;
}

// The core's frame of the contact, for the calls that take one.
static inline void engineFrame(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &d, GbContactFrame &f)
{
    const EngineContact c = engineContact(d);
    if (granbond_contact_frame_normal(c.n, c.distance, c.radius_i, c.radius_j, c.v_i, c.v_j, c.w_i, c.w_j, &f) !=
        GB_STATUS_OK)
        voigtFailed(lmp, d, "model voigt");
}

// Adds a force on i (and its opposite on j for a pair) and the torques.
static inline void addLoads(const SurfacesIntersectData &d, ForceData &i_forces, ForceData &j_forces,
                            const double *force_i, const double *torque_i, const double *torque_j)
{
    if (d.is_wall) {
        // a wall element may carry only part of the contact (multicontact)
        const double share = d.area_ratio;
        for (int k = 0; k < 3; k++) {
            addTo(i_forces.delta_F[k], share * fresh(force_i[k]));
            addTo(i_forces.delta_torque[k], share * fresh(torque_i[k]));
        }
        return;
    }
    addScalarPairLoads(i_forces, j_forces, force_i, torque_i, torque_j);
}

void voigtFailed(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &d, const char *who)
{
    char where[160];
    if (d.is_wall)
        std::snprintf(where, sizeof where, "atom %ld and a wall", static_cast<long>(lmp->atom->tag[d.i]));
    else
        std::snprintf(where, sizeof where, "atoms %ld and %ld", static_cast<long>(lmp->atom->tag[d.i]),
                      static_cast<long>(lmp->atom->tag[d.j]));
    endRunOnThisRank(lmp, FLERR,
                     std::string(who) + ": " + where + " at step " +
                         std::to_string(static_cast<long long>(lmp->update->ntimestep)) + ": " + coreReason());
}

// ------------------------------------------------------------ the sub-models
//
//   pair_style gran model voigt [switches of the normal part] tangential voigt rolling_friction voigt ...
//
// Each part reads the rows of its part of the core's Voigt table
// (docs/reference/voigt.md); `model voigt` reads the tangential part's as
// well, to be handed to whichever tangential or rolling model follows
// through sidata, so stock `tangential history` works after it.

namespace {

// Each part's first slot of the contact state, the name its history offset
// goes by and its bit of a pair's contact flag; in the order of
// GbContactPart.
struct PartSlots {
    const char *firstSlot, *offsetName;
    int flag;
};
const PartSlots kParts[3] = {
    {0, 0, CONTACT_NORMAL_MODEL},
    {"tangential_spring_x", "voigt_tangential_spring", CONTACT_TANGENTIAL_MODEL},
    {"rolling_angle_x", "voigt_rolling_angle", CONTACT_ROLLING_MODEL},
};

// What the deck calls the sub-model of `part` and the parts it reads: the
// core's (part < 3, read).
GbSubModel subModel(GbContactPart part)
{
    GbSubModel sub;
    if (granbond_voigt_sub_model(part, &sub) != GB_STATUS_OK) std::abort();
    return sub;
}

}

VoigtSubModel::VoigtSubModel(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup, ContactModelBase *cmb,
                             GbContactPart part) :
    Pointers(lmp),
    part_(part),
    sub_(subModel(part)),
    contactFlag_(kParts[part].flag),
    owner_(cmb),
    whole_(false),
    skip_(false),
    fusedRolling_(false),
    offset_(-1),
    pairInPlace_(false),
    passInPlace_(false),
    pairState_(0),
    pairModels_(0),
    pairStride_(0),
    pairDt_(0.0),
    wall_(cmb->is_wall()),
    checkPending_(true),
    checkedNatoms_(-1)
{
    share_ = VoigtContactShare::attach(owner_, &computesFrame_);
    if (part == GB_CONTACT_PART_NORMAL) {
        share_->normal = true;
        return;
    }
    offset_ = registerStateSlots(hsetup, GB_STATE_KIND_CONTACT, error,
                                 slotNamed(GB_STATE_KIND_CONTACT, kParts[part].firstSlot, error), 3, "voigt_");
    cmb->add_history_offset(kParts[part].offsetName, offset_);
    (part == GB_CONTACT_PART_TANGENTIAL ? share_->tangential_offset : share_->rolling_offset) = offset_;
}

VoigtSubModel::~VoigtSubModel() { VoigtContactShare::detach(owner_); }

void VoigtSubModel::connectToProperties(::PropertyRegistry &registry)
{
    const unsigned own = partBit(part_);
    share_->connect(registry, sub_.words, sub_.reads);
    const int ntypes = registry.max_type();
    // every row the part reads: model voigt's tangential rows are the
    // spring a stock tangential model integrates, which its time-step
    // check counts
    models_.build(error, sub_.words, ntypes, share_->params(error, sub_.words, ntypes, sub_.reads, own));
    share_->contribute(error, sub_.words, ntypes, sub_.reads);
    // every sub-model exists by now
    whole_ = part_ == GB_CONTACT_PART_NORMAL && share_->fused();
    fusedRolling_ = share_->fusedRolling();
    skip_ = part_ == GB_CONTACT_PART_TANGENTIAL ? share_->fused()
          : part_ == GB_CONTACT_PART_ROLLING    ? fusedRolling_
                                                : false;
    pairInPlace_ = whole_ && fusedRolling_ && !wall_ && !share_->bondMayHold();
    passInPlace_ = false;
    pairState_ = share_->tangential_offset;
    checkPending_ = true;
}

void VoigtSubModel::checkTimestep()
{
    const bool runStart = checkPending_;
    checkPending_ = false;
    checkedNatoms_ = atom->natoms;
    const VoigtModelTable &table = whole_ ? share_->fusedTable() : models_;
    const int ntypes = table.ntypes();
    const std::vector<GbTypeBodies> bodies =
        gatherTypeBodies(ntypes, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    GbCheckReport report;
    if (granbond_voigt_timestep_check(table.data(), ntypes, bodies.data(), update->dt, update->unit_style,
                                      sub_.words, &report) !=
        GB_STATUS_OK)
        endRun(error, FLERR, std::string(sub_.words) + ": " + coreReason());
    if (timestepWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
}

void VoigtSubModel::handOn(SurfacesIntersectData &sidata)
{
    const GbVoigtParams &p = share_->whole(sidata.itype, sidata.jtype);
    sidata.kn = p.k_n;
    sidata.kt = p.k_t;
    sidata.gamman = p.gamma_n;
    sidata.gammat = p.gamma_t;
}

// One step of the fused contact on `state` with the frame's fields straight
// from the engine's data and the core's unchecked entry (the models were
// validated when built, dt by the engine; a non-finite result is still
// caught); sets the engine's normal force.
inline void VoigtSubModel::stepFused(SurfacesIntersectData &sidata, double *state, GbContactOutput &out)
{
    const EngineContact c = engineContact(sidata);
    if (granbond_voigt_compute_normal_unchecked(share_->fusedModel(sidata.itype, sidata.jtype), c.n, c.distance,
                                                c.radius_i, c.radius_j, c.v_i, c.v_j, c.w_i, c.w_j, update->dt, state,
                                                &out) != GB_STATUS_OK)
        voigtFailed(lmp, sidata, sub_.words);
    sidata.Fn = fresh(out.normal_force);
}

// normal + tangential (+ rolling) voigt in one core call, the hot path of
// voigt x voigt (x voigt). The tangential and rolling voigt models then add
// nothing themselves.
//
// The common case (rolling voigt too, a real force step, no bond holding
// the contact) steps the stored state in place; every other case is
// wholeContactAside's, out of line, so this path copies nothing and keeps
// few registers.
void VoigtSubModel::wholeContact(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    if (!fusedRolling_ || !(sidata.computeflag && sidata.shearupdate) || share_->heldByBond(sidata)) {
        wholeContactAside(sidata, i_forces, j_forces);
        return;
    }
    GbContactOutput out;
    stepFused(sidata, &sidata.contact_history[share_->tangential_offset], out);
#if defined(__SSE2__)
    if (!sidata.is_wall) {
        addPairLoads(i_forces, j_forces, out);
        return;
    }
#endif
    addLoads(sidata, i_forces, j_forces, out.force_i, out.torque_i, out.torque_j);
}

// Every case here steps or evaluates a copy of the stored state.
void VoigtSubModel::wholeContactAside(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    // stock rolling models after voigt x voigt read kn, kt, ... (epsd2: kt)
    if (!fusedRolling_) handOn(sidata);
    double *const stored = &sidata.contact_history[share_->tangential_offset];
    double scratch[GRANBOND_CONTACT_STATE_LEN];
    bool writeBack;
    // the core writes 6 slots; without rolling voigt only 3 are ours
    double *const state =
        slots(sidata, stored, fusedRolling_ ? GRANBOND_CONTACT_STATE_LEN : 3, GRANBOND_CONTACT_STATE_LEN, scratch,
              &writeBack);
    GbContactOutput out;
    if (sidata.computeflag && sidata.shearupdate) {
        stepFused(sidata, state, out);
        for (int k = 0; writeBack && k < 3; k++)
            stored[k] = scratch[k];
    } else {
        GbContactFrame frame;
        engineFrame(lmp, sidata, frame);
        if (granbond_voigt_evaluate_frame(share_->fusedModel(sidata.itype, sidata.jtype), &frame, state, &out) !=
            GB_STATUS_OK)
            voigtFailed(lmp, sidata, sub_.words);
        sidata.Fn = out.normal_force;
    }
    addLoads(sidata, i_forces, j_forces, out.force_i, out.torque_i, out.torque_j);
}

double *VoigtSubModel::slots(const SurfacesIntersectData &sidata, double *stored, int own, int len, double *scratch,
                             bool *writeBack)
{
    // the history moves on only in a real force step (not at setup or for
    // a per-contact output pass); under a bond that holds the contact, the
    // loads are a fresh contact's, in case the bond breaks in this step's
    // pair callback, and the history stays at zero
    const bool force = sidata.computeflag && sidata.shearupdate;
    const bool held = force && share_->heldByBond(sidata);
    *writeBack = force && !held && own < len;
    if (force && !held && own == len) return stored;
    for (int k = 0; k < len; k++)
        scratch[k] = !held && k < own ? stored[k] : 0.0;
    for (int k = 0; held && k < own; k++)
        stored[k] = 0.0;
    return scratch;
}

double *VoigtSubModel::begin(const SurfacesIntersectData &sidata, bool always, double *scratch)
{
    if (computesFrame_ || always) engineFrame(lmp, sidata, share_->frame);
    bool writeBack;
    return slots(sidata, &sidata.contact_history[offset_], 3, 3, scratch, &writeBack);
}

void VoigtSubModel::surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
{
    if (part_ == GB_CONTACT_PART_NORMAL) return;
    // apart: the contact is over and its history forgotten
    if (scdata.contact_flags) *scdata.contact_flags &= ~contactFlag_;
    if (!scdata.contact_history) return;
    double *const slots = &scdata.contact_history[offset_];
    slots[0] = slots[1] = slots[2] = 0.0;
}

// The normal part: the normal force along the frame's normal, left in
// sidata.Fn for the cap of the tangential and rolling parts, which follow
// any normal model. The tangential part: Cundall-Strack spring-dashpot with
// the Coulomb cap; its history the spring elongation. The rolling part:
// Iwashita-Oda rolling resistance (spring, dashpot, cap mu_r |Fn| R*, plus
// viscous rolling resistance); its history the rolling angle. Setup and
// output passes get the loads of the stored history, not advanced.
void VoigtSubModel::partOnly(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    const GbVoigtModel *model = models_.at(sidata.itype, sidata.jtype);
    const double none[3] = {0.0, 0.0, 0.0};
    if (part_ == GB_CONTACT_PART_NORMAL) {
        handOn(sidata);
        GbContactFrame &frame = share_->frame;
        engineFrame(lmp, sidata, frame);
        double fn = 0.0;
        if (granbond_voigt_normal_force(model, &frame, &fn) != GB_STATUS_OK) voigtFailed(lmp, sidata, sub_.words);
        sidata.Fn = fn;
        const double force_i[3] = {fn * frame.n[0], fn * frame.n[1], fn * frame.n[2]};
        addLoads(sidata, i_forces, j_forces, force_i, none, none);
        return;
    }
    const bool advance = sidata.computeflag && sidata.shearupdate;
    double scratch[3];
    if (part_ == GB_CONTACT_PART_TANGENTIAL) {
        double *const spring = begin(sidata, false, scratch);
        GbTangentialOutput out;
        const GbStatus status =
            !advance ? granbond_voigt_tangential_evaluate(model, &share_->frame, sidata.Fn, spring, &out)
                     : granbond_voigt_tangential(model, &share_->frame, sidata.Fn, update->dt, spring, &out);
        if (status != GB_STATUS_OK) voigtFailed(lmp, sidata, sub_.words);
        addLoads(sidata, i_forces, j_forces, out.force_i, out.torque_i, out.torque_j);
        return;
    }
    // the fused normal model leaves no frame behind
    double *const angle = begin(sidata, share_->fused(), scratch);
    double torque_i[3];
    int32_t slip = 0;
    const GbStatus status =
        !advance ? granbond_voigt_rolling_evaluate(model, &share_->frame, sidata.Fn, angle, torque_i, &slip)
                 : granbond_voigt_rolling(model, &share_->frame, sidata.Fn, update->dt, angle, torque_i, &slip);
    if (status != GB_STATUS_OK) voigtFailed(lmp, sidata, sub_.words);
    const double torque_j[3] = {-torque_i[0], -torque_i[1], -torque_i[2]};
    addLoads(sidata, i_forces, j_forces, none, torque_i, torque_j);
}

}
}
