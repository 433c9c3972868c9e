// liggghts-granbond: drop-in replacement for the stock `liggghts` executable
// (same command line: -in, -echo, -log, -var, ...; run it under mpirun the
// same way) that carries the granbond contact models.
#include <mpi.h>
#include <cstdio>
#include <cstring>
#include "lammps.h"
#include "input.h"
#include "launcher_version.h"
#include "universe.h"

extern "C" int granbond_liggghts_registered(void);
extern "C" void granbond_liggghts_register_styles(void *lmp);
extern "C" unsigned granbond_liggghts_core_abi_version(void);

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    if (granbond::askedForVersion(argc, argv)) {
        granbond::QuietArgs quiet("liggghts-granbond");
        LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(quiet.argc, quiet.argv, MPI_COMM_WORLD);
        // "Version LIGGGHTS-PUBLIC 3.8.0, compiled ..."
        const char *version = lmp->universe->version;
        if (std::strncmp(version, "Version ", 8) == 0) version += 8;
        granbond::printVersions(version, granbond_liggghts_core_abi_version());
        delete lmp;
        MPI_Finalize();
        return 0;
    }
    // referencing the adapter keeps the linker from dropping it (--as-needed);
    // its global constructor has already registered the models
    if (granbond_liggghts_registered() <= 0)
        std::fprintf(stderr, "granbond: warning: no model combination registered\n");
    LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    // compute bond/counter, fix bond/breaklog: usable before pair_style too
    granbond_liggghts_register_styles(lmp);
    lmp->input->file();
    delete lmp;
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Finalize();
    return 0;
}
