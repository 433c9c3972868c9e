// The log of broken bonds, one line per bond, the same in both engines'
// `fix bond/breaklog` (docs/reference/fix_bond_breaklog.md):
//
//     step id_i id_j x y z mode sigma tau sigma_max tau_max
//
// The adapters fill one BreakEvent per bond that broke on the rank that
// counts it (each bond once over all ranks); rank 0 gathers, sorts by step
// and ids, and writes, so the file does not depend on the number of ranks.
// The centre and the limits are the core's (granbond_bond_centre,
// granbond_bond_stress_limits).
#ifndef GRANBOND_BREAK_LOG_H
#define GRANBOND_BREAK_LOG_H

#include "granbond.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace granbond {

// Doubles only: the events travel to rank 0 as one MPI_DOUBLE array.
struct BreakEvent {
    double step;            // time step
    double tag_i;           // lower atom id of a pair, the particle for a wall bond
    double tag_j;           // other atom id; 0 for a wall
    double x[3];            // bond centre (a wall bond: the wall point)
    double mode;            // GbBreakMode
    double sigma, tau;      // section stresses of the step that broke it
    double sigmaMax, tauMax;   // their limits at that step (0 in distance mode)
};

inline const char *breakLogHeader()
{
    return "# step id_i id_j x y z mode sigma tau sigma_max tau_max   (id_j 0: a wall bond)\n";
}

inline const char *breakModeName(double mode)
{
    switch (static_cast<int>(mode)) {
    case GB_BREAK_MODE_DISTANCE: return "distance";
    case GB_BREAK_MODE_TENSION: return "tension";
    case GB_BREAK_MODE_COMPRESSION: return "compression";
    case GB_BREAK_MODE_SHEAR: return "shear";
    default: return "unknown";
    }
}

// The event of a bond of `model` that broke in step `step` with `out`;
// sphere j of radius `radius_j` at `x_j` (a wall: radius 0 at the wall
// point, `tag_j` 0). On failure the core's message says why.
inline GbStatus makeBreakEvent(const GbBondModel *model, const GbBondOutput &out, const double *x_i,
                               const double *x_j, double radius_i, double radius_j, double tag_i, double tag_j,
                               double step, BreakEvent &e)
{
    GbStatus s = granbond_bond_centre(x_i, x_j, radius_i, radius_j, e.x);
    if (s != GB_STATUS_OK) return s;
    s = granbond_bond_stress_limits(model, out.delta, &e.sigmaMax, &e.tauMax);
    if (s != GB_STATUS_OK) return s;
    e.step = step;
    e.tag_i = tag_j == 0.0 ? tag_i : std::min(tag_i, tag_j);
    e.tag_j = tag_j == 0.0 ? 0.0 : std::max(tag_i, tag_j);
    e.mode = out.break_mode;
    e.sigma = out.sigma;
    e.tau = out.tau;
    return GB_STATUS_OK;
}

// The event of the bond between atoms i and j of an engine's `atom` that
// broke with `out`, at `step`: the atom with the smaller id first.
template<class Atom>
GbStatus makeBreakEvent(const GbBondModel *model, const GbBondOutput &out, const Atom *atom, int i, int j,
                        double step, BreakEvent &e)
{
    const int lo = atom->tag[i] < atom->tag[j] ? i : j, hi = lo == i ? j : i;
    return makeBreakEvent(model, out, atom->x[lo], atom->x[hi], atom->radius[lo], atom->radius[hi],
                          static_cast<double>(atom->tag[lo]), static_cast<double>(atom->tag[hi]), step, e);
}

// Gathers every rank's `mine` on rank 0 (and clears it), which writes them
// to `file` sorted by step and ids. Collective.
inline void writeBreakEvents(std::vector<BreakEvent> &mine, FILE *file, MPI_Comm world)
{
    int me = 0, nprocs = 1;
    MPI_Comm_rank(world, &me);
    MPI_Comm_size(world, &nprocs);
    const int fields = sizeof(BreakEvent) / sizeof(double);
    int count = static_cast<int>(mine.size()) * fields;
    std::vector<int> counts(nprocs), offsets(nprocs);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
    int total = 0;
    if (me == 0)
        for (int p = 0; p < nprocs; p++) {
            offsets[p] = total;
            total += counts[p];
        }
    std::vector<BreakEvent> all(me == 0 ? total / fields : 0);
    MPI_Gatherv(reinterpret_cast<double *>(mine.data()), count, MPI_DOUBLE, reinterpret_cast<double *>(all.data()),
                counts.data(), offsets.data(), MPI_DOUBLE, 0, world);
    mine.clear();
    if (me != 0 || all.empty() || !file) return;
    std::sort(all.begin(), all.end(), [](const BreakEvent &a, const BreakEvent &b) {
        if (a.step != b.step) return a.step < b.step;
        if (a.tag_i != b.tag_i) return a.tag_i < b.tag_i;
        return a.tag_j < b.tag_j;
    });
    for (const BreakEvent &e : all)
        fprintf(file, "%.0f %.0f %.0f %.10g %.10g %.10g %s %.6g %.6g %.6g %.6g\n", e.step, e.tag_i, e.tag_j, e.x[0],
                e.x[1], e.x[2], breakModeName(e.mode), e.sigma, e.tau, e.sigmaMax, e.tauMax);
    fflush(file);
}

// The words of `fix ID group bond/breaklog FILE [every N]` and the file
// they name, the same in both engines' fix: rank 0 opens the file and
// writes the header, and every rank's events go to it.
class BreakLogFile {
public:
    BreakLogFile() = default;
    BreakLogFile(const BreakLogFile &) = delete;
    BreakLogFile &operator=(const BreakLogFile &) = delete;
    ~BreakLogFile()
    {
        if (file_) std::fclose(file_);
    }

    // Reads the words after the style (arg[3] on); `every`: how many steps
    // apart the log is written (100 unless given). Returns what is wrong,
    // naming the word, or an empty string.
    static std::string words(int narg, char **arg, int &every)
    {
        if (narg < 4) return "expected fix ID group bond/breaklog FILE [every N]";
        every = 100;
        for (int iarg = 4; iarg < narg; iarg += 2) {
            if (std::strcmp(arg[iarg], "every") != 0 || iarg + 1 >= narg)
                return std::string("unknown keyword '") + arg[iarg] + "' (the only one is: every N)";
            char *end = nullptr;
            const long n = std::strtol(arg[iarg + 1], &end, 10);
            if (end == arg[iarg + 1] || *end != '\0' || n < 1 || n > 1000000000)
                return std::string("every must be an integer >= 1, got '") + arg[iarg + 1] + "'";
            every = static_cast<int>(n);
        }
        return std::string();
    }

    // Opens `path` and writes the header on rank `me` 0; returns what went
    // wrong on this rank, or an empty string.
    std::string open(const char *path, int me)
    {
        if (me != 0) return std::string();
        file_ = std::fopen(path, "w");
        if (!file_) return std::string("cannot open ") + path;
        std::fputs(breakLogHeader(), file_);
        std::fflush(file_);
        return std::string();
    }

    // Gathers every rank's `mine` (and clears it) and writes them. Collective.
    void write(std::vector<BreakEvent> &mine, MPI_Comm world) { writeBreakEvents(mine, file_, world); }

private:
    FILE *file_ = nullptr;
};

}

#endif
