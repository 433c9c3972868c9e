// lmp-granbond: the stock LAMMPS (liblammps) with pair_style granbond
// registered; a drop-in for `lmp` (same command line, same decks, mpirun).
#include "error.h"
#include "input.h"
#include "launcher_version.h"
#include "lammps.h"

#include <cstdio>
#include <mpi.h>

extern "C" void granbond_lammps_register(void *lmp);
extern "C" unsigned granbond_lammps_core_abi_version(void);

// `clear` deletes and recreates the Force object and with it the table of
// pair styles. liblammps calls Input::clear() through the PLT, so this
// definition in the executable takes its place: the same three steps as
// LAMMPS's own, then the registration again.
void LAMMPS_NS::Input::clear()
{
    if (narg > 0) error->all(FLERR, "Illegal clear command");
    lmp->destroy();
    lmp->create();
    lmp->post_create();
    granbond_lammps_register(lmp);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    if (granbond::askedForVersion(argc, argv)) {
        granbond::QuietArgs quiet("lmp-granbond");
        LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(quiet.argc, quiet.argv, MPI_COMM_WORLD);
        char engine[96];
        std::snprintf(engine, sizeof engine, "LAMMPS (%s)", lmp->version);
        granbond::printVersions(engine, granbond_lammps_core_abi_version());
        delete lmp;
        MPI_Finalize();
        return 0;
    }
    LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    granbond_lammps_register(lmp);
    lmp->input->file();
    delete lmp;
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Finalize();
    return 0;
}
