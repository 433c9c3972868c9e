// fix granbond/reach: the hook that gives LIGGGHTS's pair loop the contact
// distance factor of each pass (contact_reach.cpp), made by cohesion
// bond/nonlinear for its pair bonds.
#ifndef GRANBOND_LIGGGHTS_CONTACT_REACH_H
#define GRANBOND_LIGGGHTS_CONTACT_REACH_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace granbond {
namespace liggghts {

inline const char *reachFixId() { return "GRANBOND_REACH"; }
inline const char *reachFixStyle() { return "granbond/reach"; }

// The fix's style known to the engine and the fix made, if the deck has none.
void ensureReachFix(LAMMPS_NS::LAMMPS *lmp);

}
}

#endif
