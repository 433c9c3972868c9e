// fix granbond/wallbonds: the home of one wall fix's bonds (docs/development.md,
// "Wall bonds: one per sphere and wall"). It holds the core's wall-bond
// store of this rank and hands it the engine's per-atom events, so a wall
// bond moves with its sphere: arrays grown, atoms copied (sort, deletion,
// migration) and created, a sphere's bonds packed for another rank or a
// restart file and unpacked there under the sphere's id; the restart file
// also names the wall fix's meshes in the order that numbers the walls,
// so a deck that lists them in another order finds each bond's mesh.
// Made by
// cohesion bond/nonlinear of a fix wall/gran, one per wall fix, named after
// it (wallBondsFixId). Translation only: every rule is the core's.
#ifndef GRANBOND_LIGGGHTS_WALL_BONDS_FIX_H
#define GRANBOND_LIGGGHTS_WALL_BONDS_FIX_H

#include "liggghts_engine.h"
#include "fix.h"
#include "granbond.h"

#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

inline const char *wallBondsFixStyle() { return "granbond/wallbonds"; }
// The store of the wall fix `wallFixId`.
inline std::string wallBondsFixId(const char *wallFixId) { return std::string("GRANBOND_WALLBONDS_") + wallFixId; }

class WallBondsFix : public LAMMPS_NS::Fix {
public:
    WallBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
    ~WallBondsFix();

    int setmask() { return 0; }
    // LIGGGHTS's setup gives every atom a just-created fix's start value
    // (set_arrays) after the setup pass, which would take every sphere's
    // bonds from it; the store is right without it.
    void init() { just_created = 0; }

    void grow_arrays(int nmax);
    void copy_arrays(int i, int j, int);
    void set_arrays(int i);
    int pack_exchange(int i, double *buf);
    int unpack_exchange(int nlocal, double *buf);
    int pack_restart(int i, double *buf);
    void unpack_restart(int nlocal, int nth);
    int size_restart(int i);
    int maxsize_restart();
    double memory_usage();
    void write_restart(FILE *fp);

    // The ids of the wall fix's meshes, in the order that numbers the walls
    // (none for a primitive wall); written with restart files.
    void setMeshes(const std::vector<std::string> &meshes) { meshes_ = meshes; }
    // The intact bonds takeRestart took from the restart file on this rank.
    long long restored() const { return restored_; }

    GbWallStore *store() const { return store_; }
    // Takes the spheres' bonds kept from a restart file (restartRows) into
    // the store, each at its sphere's present local index, and renumbers
    // their walls from the file's meshes (`fileMeshes`, restartMeshes) to
    // the present ones (setMeshes): the run ends if a bond's mesh is gone.
    void takeRestart(const std::vector<double> &rows, const std::vector<std::string> &fileMeshes);
    // Raises the engine's room for one atom's data in the exchange buffers
    // to what a sphere's wall bonds take here (after bonds formed).
    void roomForExchange();

private:
    void fail(const char *what);
    GbWallStore *store_;
    std::vector<std::string> meshes_;
    long long restored_ = 0;
};

// The per-atom rows of fix `id` (style granbond/wallbonds) in the restart
// file read, as (id of the sphere, row length, row) one after the other;
// empty if the file has none. The engine hands a fix its rows when the fix
// is defined and drops them at the first run's start, where a wall model
// makes its store; so the model takes them when it is constructed (the fix
// wall/gran command) and hands them over itself (takeRestart).
std::vector<double> restartRows(LAMMPS_NS::LAMMPS *lmp, const std::string &id);

// The mesh ids fix `id` (style granbond/wallbonds) wrote to the restart file
// read, in the order that numbered the walls there; empty if the file has
// none (a primitive wall).
std::vector<std::string> restartMeshes(LAMMPS_NS::LAMMPS *lmp, const std::string &id);

// The same for the global state of fix granbond/atoms (the bond counters'
// totals), which a wall model makes at the first run's start where no pair
// model made it before: empty if the file has none.
std::vector<char> atomsRestartState(LAMMPS_NS::LAMMPS *lmp);

LAMMPS_NS::Fix *createWallBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

}
}

#endif
