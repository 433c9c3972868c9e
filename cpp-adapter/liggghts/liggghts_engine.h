// The LIGGGHTS headers every adapter translation unit needs, in the order
// the stock Debian LIGGGHTS 3.8 requires, and checks that our view of the
// engine's structs matches the compiled library.
#ifndef GRANBOND_LIGGGHTS_ENGINE_H
#define GRANBOND_LIGGGHTS_ENGINE_H

#include <mpi.h>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include "lammps.h"
#include "pointers.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "neigh_list.h"
#include "update.h"
#include "fix_insert_stream.h"      // must precede pair_gran_base.h
#include "granular_pair_style.h"
#include "granular_wall.h"
#include "contact_models.h"
#include "cohesion_model_base.h"
#include "global_properties.h"
#include "property_registry.h"
#include "settings.h"

// The stock library was compiled without these; struct layouts must match.
#if defined(NONSPHERICAL_ACTIVE_FLAG) || defined(SUPERQUADRIC_ACTIVE_FLAG) || defined(CONVEX_ACTIVE_FLAG)
#error "Debian libliggghts 3.8 is built without NONSPHERICAL/SUPERQUADRIC/CONVEX flags"
#endif
static_assert(sizeof(LIGGGHTS::ContactModels::ForceData) == 48 &&
                  offsetof(LIGGGHTS::ContactModels::ForceData, delta_torque) == 24,
              "ForceData layout: delta_F[3], delta_torque[3]");
static_assert(offsetof(LIGGGHTS::ContactModels::SurfacesCloseData, computeflag) == 156,
              "SurfacesCloseData layout differs from the stock library");

#endif
