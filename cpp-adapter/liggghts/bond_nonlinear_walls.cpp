// cohesion bond/nonlinear on a fix wall/gran: the wall's loop reports each
// contact of a sphere with a wall element (a mesh triangle, or a primitive
// wall); the bond of the sphere and the wall lives in the core's wall-bond
// store (fix granbond/wallbonds, wall_bonds_fix.h; docs/development.md,
// "Wall bonds: one per sphere and wall"), which says for each contact
// whether the bond acts there, holds the sphere there, or is absent.
// Translation only: the rules are the core's.
#include "bond_ledger.h"
#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"
#include "core_message.h"
#include "fix_granbond_atoms.h"
#include "fix_granbond_bonds.h"
#include "store_check.h"
#include "store_pass.h"
#include "wall_bonds_fix.h"

#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"

#include <cstdint>
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

// The book's refresh of a wall model's counts (bond_book.h).
void refreshWallTally(void *owner, bool collective)
{
    BondNonlinearCohesion *model = static_cast<BondNonlinearCohesion *>(owner);
    if (collective)
        model->warnWallLosses();
    else
        model->refreshWall();
}

}

// The wall fix this model belongs to, and the store of its bonds: found
// again (read_restart brings its spheres' bonds back), or made.
void BondNonlinearCohesion::connectWall()
{
    if (!wallFix_) endRun(error, FLERR, "cohesion bond/nonlinear: a wall model outside a fix wall/gran");
    const std::string id = wallBondsFixId(wallFix_->id);
    const bool made = modify->find_fix(id.c_str()) < 0;
    wallBonds_ = dynamic_cast<WallBondsFix *>(fixOrNew(lmp, id.c_str(), wallBondsFixStyle()));
    if (!wallBonds_) endRun(error, FLERR, "cohesion bond/nonlinear: fix " + id + " was deleted or replaced");
    // the wall numbers are the meshes' places in the wall fix
    std::vector<std::string> meshes;
    LAMMPS_NS::FixMeshSurface **list = wallFix_->mesh_list();
    for (int k = 0; list && k < wallFix_->n_meshes(); k++) meshes.push_back(list[k]->id);
    wallBonds_->setMeshes(meshes);
    // a restart file's wall bonds, read before this first run
    if (made) wallBonds_->takeRestart(wallRestart_, wallRestartMeshes_);
    wallRestart_ = std::vector<double>();
    wallRestartMeshes_ = std::vector<std::string>();
    // the bond counters' totals go into restart files with this fix; made
    // here (no pair model made it before), it takes the file's totals
    const bool atomsMade = modify->find_fix(atomsFixId()) < 0;
    atoms_ = static_cast<FixGranbondAtoms *>(fixOrNew(lmp, atomsFixId(), atomsFixStyle()));
    if (atomsMade && atoms_ && !atomsRestart_.empty()) atoms_->restart(atomsRestart_.data());
    atomsRestart_ = std::vector<char>();
    tally_.refresh = &refreshWallTally;
    tally_.owner = this;
    wallBonds_->roomForExchange();
    if (checkStore_ && comm->me == 0) {
        const std::string said = "cohesion bond/nonlinear (wall " + std::string(wallFix_->id) +
                                 "): recounting the wall bonds at every count of compute bond/counter "
                                 "(GRANBOND_CHECK_STORE)\n";
        if (screen) fputs(said.c_str(), screen);
        if (logfile) fputs(said.c_str(), logfile);
    }
    wallLinkedAt_ = -1;
    wallPass_ = -1;
}

// The wall bonds lost since the last warning, with their causes, told
// once per model (collective: every rank has the same wall models).
void BondNonlinearCohesion::warnWallLosses()
{
    if (!wallBonds_) return;
    refreshWall();
    if (checkStore_) checkWallStore();
    GbStoreCounts c;
    std::memset(&c, 0, sizeof c);
    granbond_wall_store_counts(wallBonds_->store(), &c);
    const int64_t mine[4] = {c.lost_owner_gone - wallLostTold_.lost_owner_gone,
                             c.lost_partner_unreached - wallLostTold_.lost_partner_unreached,
                             c.lost_id_reused - wallLostTold_.lost_id_reused, 0};
    wallLostTold_ = c;
    const std::string lost =
        ledgerNotice(GRANBOND_NOTICE_WALL_LOST_LIGGGHTS, mine, update->ntimestep, wallFix_->id, world);
    if (!lost.empty() && comm->me == 0) error->warning(FLERR, lost.c_str());
}

// GRANBOND_CHECK_STORE, where the counts are read over all ranks (compute
// bond/counter): the wall bonds recounted against the engine's atoms
// (checkWallBonds). A mismatch ends the run.
void BondNonlinearCohesion::checkWallStore()
{
    GbAtomIds ids = atomIdsOf(atom);
    ids.count = static_cast<size_t>(atom->nlocal);
    const std::string wrong = checkWallBonds(wallBonds_->store(), wallBonds_->restored(), ids, world);
    int bad = !wrong.empty(), anyBad = 0;
    MPI_Allreduce(&bad, &anyBad, 1, MPI_INT, MPI_MAX, world);
    if (bad)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear (wall " + std::string(wallFix_->id) +
                                         "): store check at step " +
                                         std::to_string(static_cast<long long>(update->ntimestep)) + ": " + wrong);
    if (anyBad) endRun(error, FLERR, "cohesion bond/nonlinear: wall store check failed on another rank");
}

// Before the counts are read (compute bond/counter, restart files): the
// store relinked if atoms moved since, its counts taken.
void BondNonlinearCohesion::refreshWall()
{
    if (!wallBonds_) return;
    if (neighbor->ncalls != wallLinkedAt_) linkWall();
    syncWallTally();
}

// After atoms moved: the bonds of spheres that left the system, or whose
// ids new atoms took over, leave the store (counted lost by the core).
void BondNonlinearCohesion::linkWall()
{
    GbAtomIds ids = atomIdsOf(atom);
    ids.count = static_cast<size_t>(atom->nlocal);
    if (granbond_wall_store_link(wallBonds_->store(), &ids) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR, "cohesion bond/nonlinear: finding the wall bonds' spheres: " + coreReason());
    wallLinkedAt_ = neighbor->ncalls;
}

void BondNonlinearCohesion::syncWallTally()
{
    GbStoreCounts c;
    std::memset(&c, 0, sizeof c);
    granbond_wall_store_counts(wallBonds_->store(), &c);
    tally_.take(c);
    tally_.passStep = update->ntimestep;
}

// The wall's number in the store: the mesh's place in the wall fix (a
// primitive wall is wall 0).
uint32_t BondNonlinearCohesion::wallNumber(const SurfacesCloseData &d) const
{
    if (!d.fix_mesh) return 0;
    LAMMPS_NS::FixMeshSurface **meshes = wallFix_->mesh_list();
    for (int k = 0; k < wallFix_->n_meshes(); k++)
        if (meshes[k] == d.fix_mesh) return static_cast<uint32_t>(k);
    return 0;
}

// One contact of the sphere with the wall, as the store answers it
// (GB_WALL_ACT_*); `out` holds the bond's loads where it acts here, or
// the break where it broke.
int BondNonlinearCohesion::visitWall(SurfacesCloseData &d, GbBondOutput &out)
{
    const GbBondModel *model = parameters_.model(d.itype, d.jtype);
    if (!model || !d.contact_history) {
        failed(d.i, d.j, model ? "contact history lookup" : "model lookup (types not connected)");
        return GB_WALL_ACT_CONTACT;
    }
    GbWallContact c;
    std::memset(&c, 0, sizeof c);
    const bool output = !d.computeflag, setup = d.computeflag && !d.shearupdate;
    c.kind = output ? GB_WALL_PASS_OUTPUT : setup ? GB_WALL_PASS_SETUP : GB_WALL_PASS_FORCE;
    c.step = update->ntimestep;
    c.pass = 2 * static_cast<int64_t>(update->ntimestep) + (setup ? 1 : 0);
    const bool begins = !output && c.pass != wallPass_;
    if (begins) {
        // a force or setup pass begins here: atoms may have moved since
        if (update->setupflag || neighbor->ncalls != wallLinkedAt_) linkWall();
        wallPass_ = c.pass;
    }
    c.atom = static_cast<size_t>(d.i);
    c.id = static_cast<int64_t>(atom->tag[d.i]);
    c.wall = wallNumber(d);
    c.element = static_cast<int64_t>(reinterpret_cast<intptr_t>(d.contact_history));
    c.dt = update->dt;
    c.may_create = c.kind == GB_WALL_PASS_FORCE && granbond_bond_creates_at(model, update->ntimestep);
    copy3(c.sphere.x, atom->x[d.i]);
    copy3(c.sphere.v, atom->v[d.i]);
    copy3(c.sphere.w, atom->omega[d.i]);
    c.sphere.radius = d.radi;
    if (d.v_j) copy3(c.wall_velocity, d.v_j);
    for (int k = 0; k < 3; k++) c.contact_point[k] = atom->x[d.i][k] - d.delta[k];
    GbWallVisit v;
    if (granbond_wall_store_visit(wallBonds_->store(), model, &c, &v) != GB_STATUS_OK)
        failed(d.i, d.j, "granbond_wall_store_visit");
    // the contact's flag: what the store said at this contact's latest visit
    if (!output) d.contact_history[offset_] = v.act != GB_WALL_ACT_CONTACT ? static_cast<double>(GB_BOND_STATUS_INTACT) : 0.0;
    out = v.out;
    if (v.created) wallBonds_->roomForExchange();
    if (v.out.break_mode != GB_BREAK_MODE_NONE) account(model, d.i, d.delta, out);
    // the counts change where a bond formed or broke, and at a pass's first
    // contact (bonds out of the wall's reach leave the store there)
    if (begins || v.created || v.out.break_mode != GB_BREAK_MODE_NONE) syncWallTally();
    return v.act;
}

void BondNonlinearCohesion::failed(int i, int, const char *call)
{
    // a core entry's failure is told by the core's reason; the adapter's
    // own, by what it was doing
    const std::string where = "atom " + std::to_string(static_cast<long long>(atom->tag[i])) + " and wall " +
                              wallFix_->id + " at step " + std::to_string(static_cast<long long>(update->ntimestep));
    const std::string msg = std::strncmp(call, "granbond_", 9) == 0
                                ? "cohesion bond/nonlinear: " + where + ": " + coreReason()
                                : "cohesion bond/nonlinear: " + std::string(call) + " failed for " + where;
    endRunOnThisRank(lmp, FLERR, msg);
}

// A broken wall bond in the break log: the wall plays sphere j, of radius 0
// at the wall point.
void BondNonlinearCohesion::account(const GbBondModel *model, int i, const double *wallDelta, const GbBondOutput &out)
{
    BondBook &book = *book_;
    if (!book.logging()) return;
    double wall[3];
    for (int c = 0; c < 3; c++) wall[c] = atom->x[i][c] - wallDelta[c];
    BreakEvent e;
    if (granbond_break_event(model, &out, atom->x[i], wall, atom->radius[i], 0.0, static_cast<double>(atom->tag[i]),
                             0.0, static_cast<double>(update->ntimestep), &e) != GB_STATUS_OK)
        failed(i, 0, "the break log's event");
    book.record(e);
}

void BondNonlinearCohesion::apply(const GbBondOutput &out, ForceData &i_forces)
{
    for (int c = 0; c < 3; c++) {
        i_forces.delta_F[c] += out.force_i[c];
        i_forces.delta_torque[c] += out.torque_i[c];
    }
}

void BondNonlinearCohesion::intersecting(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
{
    GbBondOutput out;
    const int act = visitWall(sidata, out);
    if (act == GB_WALL_ACT_CONTACT) return;   // the contact model acts alone
    // an intact bond replaces what normal, tangential and rolling models
    // added (at every contact of the sphere with the wall), or adds to it
    // (keepsContactLoads); it acts at one contact
    if (!keepsContactLoads(sidata.itype, sidata.jtype)) {
        i_forces.reset();
        j_forces.reset();
    }
    if (act == GB_WALL_ACT_BOND) apply(out, i_forces);
}

void BondNonlinearCohesion::close(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &)
{
    GbBondOutput out;
    if (visitWall(scdata, out) != GB_WALL_ACT_BOND) return;
    apply(out, i_forces);
    scdata.has_force_update = true;   // otherwise the engine drops the forces
}

}
}
