// lmp-granbond: the stock LAMMPS (liblammps) with pair_style granbond
// registered; a drop-in for `lmp` (same command line, same decks, mpirun).
#include "error.h"
#include "input.h"
#include "lammps.h"

#include <mpi.h>

extern "C" void granbond_lammps_register(void *lmp);

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
    LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    granbond_lammps_register(lmp);
    lmp->input->file();
    delete lmp;
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Finalize();
    return 0;
}
