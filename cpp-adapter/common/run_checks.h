// The checks both adapters run at every `run` (and when the atom count
// changes): the core judges the time step and the bond's creation rules;
// this header only gathers what the core needs from the engine's atoms and
// keeps each warning from being printed twice.
#ifndef GRANBOND_RUN_CHECKS_H
#define GRANBOND_RUN_CHECKS_H

#include "granbond.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace granbond {

// Smallest and largest radius and lightest mass of each atom type over all
// ranks (collective; index 0 unused, a type without atoms keeps infinite
// minima).
inline std::vector<GbTypeBodies> gatherTypeBodies(int ntypes, int nlocal, const int *type, const double *radius,
                                                  const double *rmass, MPI_Comm world)
{
    const double inf = std::numeric_limits<double>::infinity();
    // minima of radius, mass and -radius (the maximum), one MPI call
    std::vector<double> local(3 * (ntypes + 1), inf), all(3 * (ntypes + 1), inf);
    for (int i = 0; i < nlocal; i++) {
        const int t = type[i];
        if (t < 1 || t > ntypes) continue;
        local[3 * t] = std::min(local[3 * t], radius[i]);
        local[3 * t + 1] = std::min(local[3 * t + 1], rmass[i]);
        local[3 * t + 2] = std::min(local[3 * t + 2], -radius[i]);
    }
    MPI_Allreduce(local.data(), all.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_MIN, world);
    std::vector<GbTypeBodies> bodies(ntypes + 1);
    for (int t = 0; t <= ntypes; t++) {
        bodies[t].radius_min = all[3 * t];
        bodies[t].mass_min = all[3 * t + 1];
        bodies[t].radius_max = std::isinf(all[3 * t + 2]) ? 0.0 : -all[3 * t + 2];
    }
    return bodies;
}

// Atom renumbering (`delete_atoms ... compress yes`, the default, or
// `reset_atom_ids`) while bonds may exist. The engines keep each pair's
// history under the partner's atom ID, so renumbered IDs would hand a
// bond's state to a pair that never bonded. `stored`: a per-atom value that
// migrates (and restarts) with the atom, the ID seen at the latest check (0:
// not seen yet). Counts the atoms whose ID changed, over all ranks
// (collective), and stores the current IDs.
template<class Stored, class Tag>
long long renumberedAtoms(int nlocal, const Tag *tag, Stored *stored, MPI_Comm world)
{
    long long mine = 0, all = 0;
    for (int i = 0; i < nlocal; i++) {
        const Stored now = static_cast<Stored>(tag[i]);
        if (stored[i] != 0 && stored[i] != now) mine++;
        stored[i] = now;
    }
    MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    return all;
}

// The error for renumbered atoms; `style` names the deck command.
inline std::string renumberedMessage(const char *style, long long count)
{
    return std::string(style) + ": " + std::to_string(count) +
           " atoms changed their atom IDs since the previous run (delete_atoms with compress yes, its "
           "default, or reset_atom_ids). Bonds are kept under the partner's atom ID, so a bond would act on "
           "a pair that never bonded. Delete atoms with `delete_atoms ... compress no`";
}

// When a time-step report is printed: at a run's start, and within a run
// only when the atoms that arrived set a new limit.
class TimestepWarning {
public:
    bool due(const GbCheckReport &report, bool runStart)
    {
        const bool say = report.level > 0 && (runStart || report.critical != last_);
        last_ = report.critical;
        return say;
    }

private:
    double last_ = 0.0;
};

// Warnings already printed, so that a finding repeated at every run is
// said once.
class SaidOnce {
public:
    // True the first time `message` is seen.
    bool first(const std::string &message) { return said_.insert(message).second; }

private:
    std::set<std::string> said_;
};

// The lines of a report's message (findings are separated by newlines).
inline std::vector<std::string> reportLines(const GbCheckReport &report)
{
    std::vector<std::string> lines;
    std::string all(report.message);
    size_t start = 0;
    while (start < all.size()) {
        size_t end = all.find('\n', start);
        if (end == std::string::npos) end = all.size();
        lines.push_back(all.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

}

#endif
