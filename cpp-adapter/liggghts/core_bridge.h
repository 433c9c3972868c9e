// Start-up glue between the engine and the core that every granbond model
// class needs: the ABI layout check and the history slots of a state kind.
#ifndef GRANBOND_LIGGGHTS_CORE_BRIDGE_H
#define GRANBOND_LIGGGHTS_CORE_BRIDGE_H

#include "liggghts_engine.h"
#include "granbond.h"

#include <string>

namespace granbond {
namespace liggghts {

// error->all / error->one with a message that outlives the call (the engine
// prints it more than once, after the caller's stack is gone).
void endRun(LAMMPS_NS::Error *error, const char *file, int line, const std::string &message);
void endRunOnThisRank(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message);

// The fix of `id` (style `style`, group all), made if the deck has none;
// null if it could not be made.
LAMMPS_NS::Fix *fixOrNew(LAMMPS_NS::LAMMPS *lmp, const char *id, const char *style);

// Ends the run (error->all) if the loaded core was built from another header.
void checkCoreLayout(LAMMPS_NS::Error *error);

// Registers the core's slots of state `kind` as contact-history values
// (names and sign-flip flags from the core); returns the offset of the first.
int registerStateSlots(LIGGGHTS::IContactHistorySetup *hsetup, GbStateKind kind, LAMMPS_NS::Error *error);

// The same for slots [first, first + count) only, their names prefixed by
// `prefix` (sub-models that each own part of one state).
int registerStateSlots(LIGGGHTS::IContactHistorySetup *hsetup, GbStateKind kind, LAMMPS_NS::Error *error,
                       size_t first, size_t count, const char *prefix);

// Where the core's slot `name` lies in state `kind` (the run ends if the
// core has no such slot): adapters find slots by name, never by number.
size_t slotNamed(GbStateKind kind, const char *name, LAMMPS_NS::Error *error);

}
}

#endif
