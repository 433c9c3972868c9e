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
#include <cstdio>
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

// Findings already printed, so that one repeated at every run is said
// once.
class SaidOnce {
public:
    // The lines of the report's message (one finding each) not printed yet.
    std::vector<std::string> fresh(const GbCheckReport &report)
    {
        std::vector<std::string> lines;
        const std::string all(report.message);
        for (size_t start = 0; start < all.size();) {
            size_t end = all.find('\n', start);
            if (end == std::string::npos) end = all.size();
            const std::string line = all.substr(start, end - start);
            if (said_.insert(line).second) lines.push_back(line);
            start = end + 1;
        }
        return lines;
    }

private:
    std::set<std::string> said_;
};

// Engines keep a pair's history under the partner's atom ID, so renumbered
// IDs (`delete_atoms ... compress yes`, its default) hand a bond's state to
// a pair that never bonded. `seen` is the per-atom value of
// FixGranbondAtoms: the ID an atom had when last seen (0: not seen yet).
// Returns how many atoms changed their ID, over all ranks (collective).
template <class Tag>
long long countRenumbered(int nlocal, const Tag *tag, const double *seen, MPI_Comm world)
{
    long long mine = 0, all = 0;
    for (int i = 0; i < nlocal; i++)
        if (seen[i] != 0.0 && seen[i] != static_cast<double>(tag[i])) mine++;
    MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    return all;
}

// The error that ends a run after renumbering while bonds exist.
inline std::string renumberedMessage(const char *style, long long renumbered)
{
    return std::string(style) + ": " + std::to_string(renumbered) +
           " atoms changed their atom IDs since the previous run (delete_atoms with compress yes, its "
           "default, or reset_atom_ids). Bonds are kept under the partner's atom ID, so a bond would act on "
           "a pair that never bonded. Delete atoms with `delete_atoms ... compress no`";
}

// The engines keep a pair's history under the partner's atom ID, so two
// images of one atom in a neighbour list share one record. That happens in
// a periodic direction shorter than twice the list's reach (the pair
// reach plus the skin): a sphere meets its own image, or one partner
// twice. A 2d run (`dimension` 2) has no images in z, whatever its extent.
// `step` >= 0: the box changed during a run (fix deform) and is checked at
// that step. Returns the error naming the first such direction, or "".
inline std::string thinPeriodicBox(const char *style, int dimension, const int periodic[3], const double length[3],
                                   double listReach, double skin, long long step = -1)
{
    for (int d = 0; d < dimension; d++) {
        if (!periodic[d] || length[d] >= 2.0 * listReach) continue;
        char text[720];
        const std::string when = step < 0 ? std::string() : " at step " + std::to_string(step) + ", as the box changed";
        std::snprintf(text, sizeof text,
                      "%s: the periodic box is %g long in %c%s, less than twice the neighbour reach %g (the pair "
                      "reach %g plus the skin %g): a sphere can meet its own periodic image, or one partner "
                      "twice, and the engine keeps a pair's contact and bond history under the partner's atom "
                      "ID, so those pairs would share one record. %s %g long in %c%s",
                      style, length[d], "xyz"[d], when.c_str(), listReach, listReach - skin, skin,
                      step < 0 ? "Make the box at least" : "Keep the box (fix deform's final size) at least",
                      2.0 * listReach, "xyz"[d], step < 0 ? " (replicate it), or use a fixed boundary there" : "");
        return text;
    }
    return std::string();
}

}

#endif
