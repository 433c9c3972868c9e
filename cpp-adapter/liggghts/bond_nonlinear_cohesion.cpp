#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

namespace {

void copy3(double *to, const double *from)
{
    to[0] = from[0];
    to[1] = from[1];
    to[2] = from[2];
}

// Position, velocity and angular velocity of local or ghost atom `i`.
void readAtom(const LAMMPS_NS::Atom *atom, int i, double *x, double *v, double *w)
{
    copy3(x, atom->x[i]);
    copy3(v, atom->v[i]);
    copy3(w, atom->omega[i]);
}

void setContactFlag(SurfacesCloseData &d, bool keep)
{
    if (!d.contact_flags) return;   // walls have none
    if (keep)
        *d.contact_flags |= CONTACT_COHESION_MODEL;   // keeps the history at re-neighbouring
    else
        *d.contact_flags &= ~CONTACT_COHESION_MODEL;
}

}

BondNonlinearCohesion::BondNonlinearCohesion(LAMMPS_NS::LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *hsetup,
                                             ContactModelBase *cmb) :
    CohesionModelBase(lmp, hsetup, cmb),
    parameters_(lmp),
    isWall_(cmb->is_wall()),
    stateLen_(granbond_state_len(cmb->is_wall() ? GB_STATE_KIND_WALL_BOND : GB_STATE_KIND_BOND)),
    offset_(-1)
{
    checkCoreLayout(error);
    offset_ = registerStateSlots(hsetup, isWall_ ? GB_STATE_KIND_WALL_BOND : GB_STATE_KIND_BOND, error);
    // the name the reference publishes, so per-contact tools can find the slots
    cmb->add_history_offset("bondnonlinear_contactflag", offset_);
}

void BondNonlinearCohesion::failed(const SurfacesCloseData &d, const char *call)
{
    char where[160];
    if (isWall_)
        snprintf(where, sizeof where, "atom %ld and a wall", static_cast<long>(atom->tag[d.i]));
    else
        snprintf(where, sizeof where, "atoms %ld and %ld", static_cast<long>(atom->tag[d.i]),
                 static_cast<long>(atom->tag[d.j]));
    const std::string msg = std::string("cohesion bond/nonlinear: ") + call + " failed for " + where +
                            " at step " + std::to_string(static_cast<long long>(update->ntimestep)) + ": " +
                            granbond_last_error_message();
    endRunOnThisRank(lmp, FLERR, msg);
}

bool BondNonlinearCohesion::advance(SurfacesCloseData &d, GbBondOutput &out)
{
    const GbBondModel *model = parameters_.model(d.itype, d.jtype);
    if (!model || !d.contact_history) {
        failed(d, model ? "contact history lookup" : "model lookup (types not connected)");
        return false;
    }
    double *const history = d.contact_history + offset_;
    // The engine asks for forces without advancing state too (setup pass,
    // per-contact output): then the bond steps on a copy.
    const bool advanceState = d.computeflag && d.shearupdate;
    double scratch[GRANBOND_WALL_BOND_STATE_LEN];
    double *state = history;
    if (!advanceState) {
        std::memcpy(scratch, history, stateLen_ * sizeof(double));
        state = scratch;
    }
    return isWall_ ? advanceWall(d, model, state, advanceState, out)
                   : advancePair(d, model, state, advanceState, out);
}

bool BondNonlinearCohesion::advancePair(SurfacesCloseData &d, const GbBondModel *model, double *state,
                                        bool advanceState, GbBondOutput &out)
{
    // atom->omega, not d.omega_i/j: in surfacesClose those are left over
    // from the previous overlapping pair
    GbPairKinematics k;
    readAtom(atom, d.i, k.x_i, k.v_i, k.w_i);
    readAtom(atom, d.j, k.x_j, k.v_j, k.w_j);
    k.radius_i = d.radi;
    k.radius_j = d.radj;

    if (advanceState) {
        int32_t created = 0;
        if (granbond_bond_try_create(model, &k, update->ntimestep, state, &created) != GB_STATUS_OK)
            failed(d, "granbond_bond_try_create");
    }
    if (state[0] != GB_BOND_STATUS_INTACT) return false;
    if (granbond_bond_compute(model, &k, update->dt, state, &out) != GB_STATUS_OK)
        failed(d, "granbond_bond_compute");
    return out.status == GB_BOND_STATUS_INTACT;
}

bool BondNonlinearCohesion::advanceWall(SurfacesCloseData &d, const GbBondModel *model, double *state,
                                        bool advanceState, GbBondOutput &out)
{
    GbSphereKinematics s;
    readAtom(atom, d.i, s.x, s.v, s.w);
    s.radius = d.radi;
    double wallVelocity[3] = {0.0, 0.0, 0.0};
    if (d.v_j) copy3(wallVelocity, d.v_j);

    if (advanceState) {
        // delta runs from the wall's contact point to the sphere centre
        const double contactPoint[3] = {s.x[0] - d.delta[0], s.x[1] - d.delta[1], s.x[2] - d.delta[2]};
        int32_t created = 0;
        if (granbond_wall_bond_try_create(model, &s, contactPoint, update->ntimestep, state, &created) !=
            GB_STATUS_OK)
            failed(d, "granbond_wall_bond_try_create");
    }
    if (state[0] != GB_BOND_STATUS_INTACT) return false;
    if (granbond_wall_bond_compute(model, &s, wallVelocity, update->dt, state, &out) != GB_STATUS_OK)
        failed(d, "granbond_wall_bond_compute");
    return out.status == GB_BOND_STATUS_INTACT;
}

void BondNonlinearCohesion::apply(const GbBondOutput &out, ForceData &i_forces, ForceData &j_forces)
{
    for (int c = 0; c < 3; c++) {
        i_forces.delta_F[c] += out.force_i[c];
        i_forces.delta_torque[c] += out.torque_i[c];
    }
    if (isWall_) return;
    for (int c = 0; c < 3; c++) {
        j_forces.delta_F[c] -= out.force_i[c];
        j_forces.delta_torque[c] += out.torque_j[c];
    }
}

void BondNonlinearCohesion::endSurfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                 ForceData &j_forces)
{
    GbBondOutput out;
    const bool intact = advance(sidata, out);
    setContactFlag(sidata, intact);
    if (!intact) return;   // the contact model acts alone
    // an intact bond replaces what normal, tangential and rolling models added
    i_forces.reset();
    j_forces.reset();
    apply(out, i_forces, j_forces);
}

void BondNonlinearCohesion::surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
{
    GbBondOutput out;
    const bool intact = advance(scdata, out);
    setContactFlag(scdata, intact);
    if (!intact) return;
    apply(out, i_forces, j_forces);
    scdata.has_force_update = true;   // otherwise the engine drops the forces
}

}
}
