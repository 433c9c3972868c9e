// Error for unregistered model combinations (see combination_check.cpp).
#ifndef GRANBOND_LIGGGHTS_COMBINATION_CHECK_H
#define GRANBOND_LIGGGHTS_COMBINATION_CHECK_H

#include "liggghts_engine.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"

namespace granbond {
namespace liggghts {

// Records a combination hash registered with the engine's factories.
void noteRegisteredCombination(int64_t hash);

// Wraps the engine's "gran" variant selector (pairs and walls) so a
// combination naming a granbond model that was not registered ends the run
// with the list of registered ones. Call after the LAMMPS constructor (which
// re-registers the engine's selector); idempotent.
void installCombinationCheck();

}
}

#endif
