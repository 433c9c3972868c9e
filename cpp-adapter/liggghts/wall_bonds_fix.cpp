#include "wall_bonds_fix.h"
#include "core_bridge.h"
#include "core_message.h"
#include "engine_member.h"
#include "fix_granbond_atoms.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <sstream>
#include <string>

namespace granbond {
namespace liggghts {

// Modify keeps the restart file's fix lists protected (engine_member.h).
typedef char **LAMMPS_NS::Modify::*NamesMember;
typedef int *LAMMPS_NS::Modify::*IndexMember;
GRANBOND_ENGINE_MEMBER(RestartIds, NamesMember, &LAMMPS_NS::Modify::id_restart_peratom);
GRANBOND_ENGINE_MEMBER(RestartStyles, NamesMember, &LAMMPS_NS::Modify::style_restart_peratom);
GRANBOND_ENGINE_MEMBER(RestartIndex, IndexMember, &LAMMPS_NS::Modify::index_restart_peratom);
GRANBOND_ENGINE_MEMBER(GlobalIds, NamesMember, &LAMMPS_NS::Modify::id_restart_global);
GRANBOND_ENGINE_MEMBER(GlobalStyles, NamesMember, &LAMMPS_NS::Modify::style_restart_global);
GRANBOND_ENGINE_MEMBER(GlobalStates, NamesMember, &LAMMPS_NS::Modify::state_restart_global);

namespace {

// The engines' callback kinds: 0 grow, 1 restart.
const int kGrow = 0, kRestart = 1;

int64_t idOf(const LAMMPS_NS::Atom *atom, int i) { return static_cast<int64_t>(atom->tag[i]); }

// The mesh list's head in a restart file, then the ids, one space apart.
const char kMeshesHead[] = "granbond wall meshes:";

std::string listed(const std::vector<std::string> &meshes)
{
    std::string s;
    for (size_t k = 0; k < meshes.size(); k++) s += (k ? ", " : "") + std::to_string(k) + " " + meshes[k];
    return meshes.empty() ? "none (a primitive wall)" : s;
}


}

std::vector<double> restartRows(LAMMPS_NS::LAMMPS *lmp, const std::string &id)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    LAMMPS_NS::Atom *atom = lmp->atom;
    char **ids = modify->*member(RestartIds()), **styles = modify->*member(RestartStyles());
    int *index = modify->*member(RestartIndex());
    std::vector<double> rows;
    for (int k = 0; k < modify->nfix_restart_peratom; k++) {
        if (id != ids[k] || std::string(wallBondsFixStyle()) != styles[k] || !atom->extra) continue;
        for (int i = 0; i < atom->nlocal; i++) {
            const double *extra = atom->extra[i];
            int m = 0;
            for (int j = 0; j < index[k]; j++) m += static_cast<int>(extra[m]);
            const int n = static_cast<int>(extra[m]) - 1;
            if (n < 1 || extra[m + 1] == 0.0) continue;   // no bond: the row's count is 0
            rows.push_back(static_cast<double>(atom->tag[i]));
            rows.push_back(n);
            rows.insert(rows.end(), extra + m + 1, extra + m + 1 + n);
        }
    }
    return rows;
}

std::vector<std::string> restartMeshes(LAMMPS_NS::LAMMPS *lmp, const std::string &id)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    char **ids = modify->*member(GlobalIds()), **styles = modify->*member(GlobalStyles());
    char **states = modify->*member(GlobalStates());
    std::vector<std::string> meshes;
    for (int k = 0; k < modify->nfix_restart_global; k++) {
        if (id != ids[k] || std::string(wallBondsFixStyle()) != styles[k]) continue;
        const std::string state(states[k]);
        if (state.compare(0, sizeof kMeshesHead - 1, kMeshesHead) != 0) continue;
        std::istringstream words(state.substr(sizeof kMeshesHead - 1));
        for (std::string w; words >> w;) meshes.push_back(w);
    }
    return meshes;
}

std::vector<char> atomsRestartState(LAMMPS_NS::LAMMPS *lmp)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    char **ids = modify->*member(GlobalIds()), **styles = modify->*member(GlobalStyles());
    char **states = modify->*member(GlobalStates());
    for (int k = 0; k < modify->nfix_restart_global; k++) {
        if (std::string(atomsFixId()) != ids[k] || std::string(atomsFixStyle()) != styles[k]) continue;
        // the state says its length: a marker, the count of values, the values
        double head[2];
        std::memcpy(head, states[k], sizeof head);
        const size_t values = head[1] >= 0.0 && head[1] <= 64.0 ? static_cast<size_t>(head[1]) : 0;
        return std::vector<char>(states[k], states[k] + (2 + values) * sizeof(double));
    }
    return std::vector<char>();
}

void WallBondsFix::takeRestart(const std::vector<double> &rows, const std::vector<std::string> &fileMeshes)
{
    std::map<int64_t, int> local;
    for (int i = 0; i < atom->nlocal; i++) local[idOf(atom, i)] = i;
    for (size_t k = 0; k + 2 <= rows.size();) {
        const int64_t id = static_cast<int64_t>(rows[k]);
        const size_t n = static_cast<size_t>(rows[k + 1]);
        const std::map<int64_t, int>::const_iterator at = local.find(id);
        size_t read = 0;
        if (at != local.end() &&
            granbond_wall_store_unpack(store_, static_cast<size_t>(at->second), id, update->ntimestep, &rows[k + 2], n,
                                       &read) != GB_STATUS_OK)
            fail("reading a sphere's wall bonds from the restart file");
        k += 2 + n;
    }
    GbStoreCounts c = {};
    granbond_wall_store_counts(store_, &c);
    restored_ = c.intact;
    // the file's wall k is the mesh of its id here (a file without mesh
    // ids, or of a primitive wall, numbers its walls as this one does)
    if (fileMeshes.empty()) return;
    std::vector<int64_t> map(fileMeshes.size(), -1);
    for (size_t k = 0; k < fileMeshes.size(); k++)
        for (size_t j = 0; j < meshes_.size(); j++)
            if (fileMeshes[k] == meshes_[j]) map[k] = static_cast<int64_t>(j);
    if (granbond_wall_store_renumber(store_, map.data(), map.size()) != GB_STATUS_OK)
        endRunOnThisRank(lmp, FLERR,
                         "fix " + std::string(id) + ": the restart file's wall bonds lie on the meshes (by wall number) " +
                             listed(fileMeshes) + "; the wall fix now lists " + listed(meshes_) +
                             ": a mesh with bonds is gone (" + coreReason() + ")");
}

WallBondsFix::WallBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), store_(nullptr)
{
    if (granbond_wall_store_new(&store_) != GB_STATUS_OK) fail("making the store");
    restart_global = 1;
    restart_peratom = 1;
    create_attribute = 1;
    grow_arrays(atom->nmax);
    atom->add_callback(kGrow);
    atom->add_callback(kRestart);
}

WallBondsFix::~WallBondsFix()
{
    atom->delete_callback(id, kGrow);
    atom->delete_callback(id, kRestart);
    granbond_wall_store_free(store_);
}

void WallBondsFix::fail(const char *what)
{
    endRunOnThisRank(lmp, FLERR, std::string("fix granbond/wallbonds: ") + what + ": " + coreReason());
}

void WallBondsFix::roomForExchange()
{
    const int room = static_cast<int>(granbond_wall_store_most_packed_len(store_));
    comm->maxexchange_fix = std::max(comm->maxexchange_fix, room);
}

void WallBondsFix::grow_arrays(int nmax)
{
    if (granbond_wall_store_grow(store_, static_cast<size_t>(nmax)) != GB_STATUS_OK) fail("growing");
}

void WallBondsFix::copy_arrays(int i, int j, int)
{
    if (granbond_wall_store_copy(store_, static_cast<size_t>(i), static_cast<size_t>(j)) != GB_STATUS_OK)
        fail("copying an atom");
}

void WallBondsFix::set_arrays(int i)
{
    if (granbond_wall_store_clear(store_, static_cast<size_t>(i)) != GB_STATUS_OK) fail("a created atom");
}

int WallBondsFix::pack_exchange(int i, double *buf)
{
    size_t written = 0;
    const size_t room = granbond_wall_store_packed_len(store_, idOf(atom, i));
    if (granbond_wall_store_pack(store_, static_cast<size_t>(i), idOf(atom, i), 1, buf, room, &written) !=
        GB_STATUS_OK)
        fail("packing a sphere's wall bonds for another rank");
    return static_cast<int>(written);
}

int WallBondsFix::unpack_exchange(int nlocal, double *buf)
{
    // the head of the packed bonds says their length; the core reads it
    // and checks the rest
    size_t n = 0, read = 0;
    if (granbond_wall_store_packed_len_in(buf, 2, &n) != GB_STATUS_OK ||
        granbond_wall_store_unpack(store_, static_cast<size_t>(nlocal), idOf(atom, nlocal), update->ntimestep, buf,
                                   n, &read) != GB_STATUS_OK)
        fail("unpacking a sphere's wall bonds from another rank");
    return static_cast<int>(read);
}

int WallBondsFix::pack_restart(int i, double *buf)
{
    size_t written = 0;
    const size_t room = granbond_wall_store_packed_len(store_, idOf(atom, i));
    if (granbond_wall_store_pack(store_, static_cast<size_t>(i), idOf(atom, i), 0, buf + 1, room, &written) !=
        GB_STATUS_OK)
        fail("packing a sphere's wall bonds for a restart file");
    buf[0] = static_cast<double>(written + 1);
    return static_cast<int>(written + 1);
}

void WallBondsFix::unpack_restart(int nlocal, int nth)
{
    double **extra = atom->extra;
    int m = 0;
    for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
    const size_t n = static_cast<size_t>(extra[nlocal][m]) - 1;
    size_t read = 0;
    GbStoreCounts before = {}, after = {};
    granbond_wall_store_counts(store_, &before);
    if (granbond_wall_store_unpack(store_, static_cast<size_t>(nlocal), idOf(atom, nlocal), update->ntimestep,
                                   &extra[nlocal][m + 1], n, &read) != GB_STATUS_OK)
        fail("reading a sphere's wall bonds from the restart file");
    granbond_wall_store_counts(store_, &after);
    restored_ += after.intact - before.intact;
}

int WallBondsFix::size_restart(int i)
{
    return static_cast<int>(granbond_wall_store_packed_len(store_, idOf(atom, i)) + 1);
}

// Called on every rank by write_restart: the most over all ranks.
int WallBondsFix::maxsize_restart()
{
    int mine = static_cast<int>(granbond_wall_store_most_packed_len(store_)) + 1, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
    return all;
}

void WallBondsFix::write_restart(FILE *fp)
{
    if (comm->me != 0) return;
    std::string state = kMeshesHead;
    for (const std::string &m : meshes_) state += " " + m;
    const int size = static_cast<int>(state.size() + 1);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(state.c_str(), 1, static_cast<size_t>(size), fp);
}

double WallBondsFix::memory_usage() { return static_cast<double>(granbond_wall_store_bytes(store_)); }

LAMMPS_NS::Fix *createWallBondsFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
    return new WallBondsFix(lmp, narg, arg);
}

}
}
