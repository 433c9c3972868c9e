// A bond type's settings in restart files as (keyword, value) rows of the
// core's table, as pair granbond writes its type pairs' (pair_restart.cpp).
#ifndef GRANBOND_LAMMPS_RESTART_ROWS_H
#define GRANBOND_LAMMPS_RESTART_ROWS_H

#include "granbond.h"

#include "error.h"

#include <cstdio>
#include <mpi.h>
#include <string>

namespace granbond {
namespace lammps {

void writeBondRows(FILE *fp, const GbBondParams &params, LAMMPS_NS::Error *error);
// Rank 0 reads, every rank gets `params`; `what` names the bond type in errors.
void readBondRows(FILE *fp, GbBondParams &params, const std::string &what, int me, MPI_Comm world,
                  LAMMPS_NS::Error *error);

}
}

#endif
