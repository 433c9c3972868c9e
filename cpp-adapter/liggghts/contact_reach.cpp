// The contact distance factor, pass by pass. LIGGGHTS keeps one factor,
// the largest any model registered: the neighbour lists (neigh_gran.cpp),
// the ghost atoms' reach (PairGran::init_one, read at each run's init), the
// mesh walls' lists (FixNeighlistMesh::pre_force after a list build), the
// walls' contact test (FixWallGran::post_force) and the pair loop read it.
// The loop visits every listed pair that is apart but within the factor
// (surfacesClose). cohesion bond/nonlinear registers its bonds' reach, so
// the lists and ghosts hold every bond's partner; the loop needs that reach
// only in a pass that can form a bond, since the bonds in the store are
// stepped without the loop. So fix granbond/reach lowers the factor to what
// the rest of the deck registered just before a force pass that can form no
// bond, and the bond model puts it back when the pair loop ends: the lists,
// the ghosts, the walls and every output see the full factor.
#include "contact_reach.h"
#include "bond_book.h"
#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"
#include "engine_member.h"

#include "fix.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cstring>
#include <map>
#include <string>

namespace granbond {
namespace liggghts {

namespace {

class ReachFix : public LAMMPS_NS::Fix {
public:
    ReachFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : LAMMPS_NS::Fix(lmp, narg, arg) {}

    int setmask() { return LAMMPS_NS::FixConst::PRE_FORCE | LAMMPS_NS::FixConst::POST_FORCE; }
    // After the list build and every other fix's work of the step, before
    // the pair loop reads the factor.
    void pre_force(int)
    {
        if (BondNonlinearCohesion *bonds = BondBook::of(lmp).pairBonds) bonds->narrowReach();
    }
    // The pair loop's end has put the factor back; a step whose pair loop
    // did not run (pair_modify compute no) has it put back here, before the
    // next list build.
    void post_force(int)
    {
        if (BondNonlinearCohesion *bonds = BondBook::of(lmp).pairBonds) bonds->widenReach();
    }
};

LAMMPS_NS::Fix *createReachFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) { return new ReachFix(lmp, narg, arg); }

}

typedef LAMMPS_NS::Fix *(*ReachFixCreator)(LAMMPS_NS::LAMMPS *, int, char **);
typedef std::map<std::string, ReachFixCreator> *LAMMPS_NS::Modify::*ReachFixStyles;
GRANBOND_ENGINE_MEMBER(ReachFixStylesTag, ReachFixStyles, &LAMMPS_NS::Modify::fix_map);

void ensureReachFix(LAMMPS_NS::LAMMPS *lmp)
{
    std::map<std::string, ReachFixCreator> *styles = lmp->modify->*member(ReachFixStylesTag());
    if (styles) (*styles)[reachFixStyle()] = &createReachFix;
    if (!dynamic_cast<ReachFix *>(fixOrNew(lmp, reachFixId(), reachFixStyle())))
        endRun(lmp->error, FLERR, "cohesion bond/nonlinear: fix granbond/reach could not be made");
}

// The factor before and after this model registered its reach: what the
// rest of the pair style and the deck need is the factor before, at the
// first run. At a later run the factor still holds this model's reach from
// the run before, so the first value stays, unless the factor moved since
// (neigh_modify contact_distance_factor, or a model registered more): then
// the value found is taken, which lowers nothing where it is the whole
// factor.
void BondNonlinearCohesion::noteReach(double before)
{
    if (isWall_) return;
    if (baseReach_ < 0.0 || before != registeredReach_) baseReach_ = before;
    registeredReach_ = neighbor->contactDistanceFactor;
    ensureReachFix(lmp);
}

namespace {

// Whether a mesh wall's lists (fix neighlist/mesh, built in its pre_force
// at a step that built the neighbour lists) come after fix granbond/reach's
// pre_force: the engine calls the fixes' pre_force in the order of its fix
// list.
bool meshListsBuiltAfterReach(LAMMPS_NS::Modify *modify)
{
    const int reach = modify->find_fix(reachFixId());
    if (reach < 0) return true;
    for (int i = reach + 1; i < modify->nfix; i++)
        if (std::strcmp(modify->fix[i]->style, "neighlist/mesh") == 0) return true;
    return false;
}

}

// A force pass lowers the factor where no bond can form in it: its step is
// no creation step of any type pair (the core's rule), no `bonded yes`
// clump waits for its bonds, and the bond takes all the contact's loads (a
// model that keeps the contact's tangential loads under the bond leaves the
// engine's visits as they were). A step that built the lists keeps the
// factor where a mesh wall builds its own lists after this point.
void BondNonlinearCohesion::narrowReach()
{
    if (isWall_ || narrowed_ || !bonds_ || update->setupflag) return;
    if (neighbor->ago == 0 && meshListsBuiltAfterReach(modify)) return;
    if (keepsTangential_ || keepsLoads_ || clumpIds_) return;
    if (!(baseReach_ < neighbor->contactDistanceFactor)) return;
    const GbBondModel *const *table = parameters_.table();
    for (size_t k = 0; k < kinds_.size(); k++)
        if (table[k] && granbond_bond_creates_at(table[k], update->ntimestep)) return;
    fullReach_ = neighbor->contactDistanceFactor;
    neighbor->contactDistanceFactor = baseReach_;
    narrowed_ = true;
}

void BondNonlinearCohesion::widenReach()
{
    if (!narrowed_) return;
    neighbor->contactDistanceFactor = fullReach_;
    narrowed_ = false;
}

}
}
